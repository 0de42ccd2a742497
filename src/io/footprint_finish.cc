// The finishing steps shared by the footprint readers: CRS -> origin -> repair -> ids, and the
// diagnostics bookkeeping (caps, --keep-going, sorting). docs/geojson.md documents the rules and
// codes; docs/osm.md how OpenStreetMap input uses them.
#include "io/footprint_finish.h"

#include "base/numbered_names.h"
#include "io/crs.h"
#include "io/map_areas.h"
#include "kernel/skeleton.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <memory>
#include <set>
#include <string_view>
#include <unordered_set>
#include <utility>

namespace insula::io {

std::string number_text(double v) {
  if (std::abs(v) < 1e15 && v == std::floor(v)) return std::to_string(static_cast<long long>(v));
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
  return std::string(buffer, end);
}

std::string quote_text(std::string_view text) {
  constexpr std::size_t kMax = 40;
  std::string out = "\"";
  out.append(text.substr(0, kMax));
  if (text.size() > kMax) out += "...";
  return out + "\"";
}

namespace {

// Where two rings of a polygon meet, or one ring meets itself, other than at the shared vertex of
// consecutive edges. O(n^2), only run to explain a polygon kernel::is_simple_polygon rejected.
struct Touch {
  std::size_t ring_a = 0;  // 0: the outer ring, k: hole k
  std::size_t ring_b = 0;
  kernel::Vec2 point;
};

bool on_segment(kernel::Vec2 a, kernel::Vec2 b, kernel::Vec2 p) {
  return kernel::cross(b - a, p - a) == 0 && std::min(a.x, b.x) <= p.x &&
         p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

std::optional<Touch> find_touch(const kernel::Polygon& polygon) {
  std::vector<const kernel::Ring*> rings{&polygon.outer};
  for (const kernel::Ring& hole : polygon.holes) rings.push_back(&hole);
  for (std::size_t ra = 0; ra < rings.size(); ++ra) {
    const kernel::Ring& a = *rings[ra];
    for (std::size_t i = 0; i < a.size(); ++i) {
      const kernel::Vec2 p = a[i];
      const kernel::Vec2 q = a[(i + 1) % a.size()];
      for (std::size_t rb = ra; rb < rings.size(); ++rb) {
        const kernel::Ring& b = *rings[rb];
        for (std::size_t j = rb == ra ? i + 1 : 0; j < b.size(); ++j) {
          if (rb == ra && (j == i + 1 || (i == 0 && j + 1 == b.size()))) continue;
          const kernel::Vec2 u = b[j];
          const kernel::Vec2 v = b[(j + 1) % b.size()];
          for (const kernel::Vec2 point : {u, v}) {
            if (on_segment(p, q, point)) return Touch{ra, rb, point};
          }
          for (const kernel::Vec2 point : {p, q}) {
            if (on_segment(u, v, point)) return Touch{ra, rb, point};
          }
        }
      }
    }
  }
  return std::nullopt;
}

bool has_three_distinct(const kernel::Ring& ring) {
  const auto second =
      std::find_if(ring.begin(), ring.end(), [&](kernel::Vec2 v) { return v != ring[0]; });
  return second != ring.end() && std::any_of(second, ring.end(), [&](kernel::Vec2 v) {
           return v != ring[0] && v != *second;
         });
}

const char* repair_code(kernel::PolygonIssueKind kind) {
  switch (kind) {
    case kernel::PolygonIssueKind::kTooFewVertices:
      return "GEO020";
    case kernel::PolygonIssueKind::kZeroArea:
      return "GEO021";
    case kernel::PolygonIssueKind::kSelfIntersection:
      return "GEO022";
    case kernel::PolygonIssueKind::kRingsIntersect:
      return "GEO023";
    case kernel::PolygonIssueKind::kHoleOutside:
      return "GEO024";
    case kernel::PolygonIssueKind::kDuplicateVertex:
      return "GEO025";
    case kernel::PolygonIssueKind::kCollinearVertex:
      return "GEO026";
    case kernel::PolygonIssueKind::kNonFinite:
    case kernel::PolygonIssueKind::kWrongOrientation:
      break;
  }
  return "GEO013";
}

// The FootprintSet::repairs key of a repaired issue.
const char* repair_kind(const kernel::PolygonIssue& issue) {
  switch (issue.kind) {
    case kernel::PolygonIssueKind::kDuplicateVertex:
      return "duplicate_vertex";
    case kernel::PolygonIssueKind::kCollinearVertex:
      return "collinear_vertex";
    case kernel::PolygonIssueKind::kSelfIntersection:
      return "spike";
    default:
      return "dropped_hole";
  }
}

// The input position nearest `point`, on ring `prefer` where there is a tie (repair may have
// dropped or reordered positions): where a message about that point should look.
void nearest_position(const kernel::Polygon& written, kernel::Vec2 point, std::size_t prefer,
                      FootprintPlace& where) {
  double best = std::numeric_limits<double>::infinity();
  std::vector<std::size_t> order{prefer};
  for (std::size_t r = 0; r <= written.holes.size(); ++r) order.push_back(r);
  for (const std::size_t r : order) {
    if (r > written.holes.size()) continue;
    const kernel::Ring& ring = r == 0 ? written.outer : written.holes[r - 1];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const kernel::Vec2 d = ring[i] - point;
      if (kernel::dot(d, d) < best) {
        best = kernel::dot(d, d);
        where.ring = r;
        where.position = i;
      }
    }
  }
}

// Three decimals are all a sliver's measures need.
std::string rounded(double v) {
  return number_text(std::round(v * 1000) / 1000);
}

std::string point_text(kernel::Vec2 p) {
  return "(" + number_text(p.x) + ", " + number_text(p.y) + ")";
}

}  // namespace

FootprintBuilder::FootprintBuilder(std::string source_name, const FootprintOptions& options,
                                   std::string options_name)
    : name_(std::move(source_name)), options_(options), options_name_(std::move(options_name)) {}

void FootprintBuilder::report(base::Severity severity, const char* code, std::string message,
                              const Location& where, std::vector<std::string> notes) {
  if (stopped_) return;
  if (severity == base::Severity::kWarning && warnings_ >= options_.max_warnings) {
    ++result_.unlisted_warnings[code != nullptr ? code : ""];
    return;
  }
  base::Diagnostic d = severity == base::Severity::kError
                           ? base::Diagnostic::error(code, std::move(message), where.span)
                           : base::Diagnostic::warning(code, std::move(message), where.span);
  d.notes = std::move(notes);
  if (severity == base::Severity::kError && ++errors_ >= options_.max_errors) {
    d.notes.push_back("too many errors (" + options_name_ + "::max_errors = " +
                      std::to_string(options_.max_errors) + "); stopped reading");
    stopped_ = true;
  }
  if (severity == base::Severity::kWarning) ++warnings_;
  pending_.push_back({where.order, std::move(d)});
}

void FootprintBuilder::feature_issue(std::size_t index, bool is_error, const char* code,
                                     const std::string& message, const Location& where,
                                     std::vector<std::string> notes) {
  if (is_error && hold_issue(index, code, message, where, notes)) return;
  RawFootprint& feature = features_[index];
  const std::string flag = options_.skip_invalid_flag.empty() ? options_name_ + "::skip_invalid"
                                                              : options_.skip_invalid_flag;
  if (is_error) {
    // Skipping: one warning per feature, its first error; the rest would repeat "skipped".
    if (options_.skip_invalid && feature.failed) return;
    if (options_.skip_invalid) {
      notes.push_back("feature skipped (" + flag + ")");
      ++result_.skipped_by_code[code];
    } else if (!hinted_skip_ && !options_.skip_invalid_flag.empty()) {
      notes.push_back(flag + " skips invalid features, each with a warning");
      hinted_skip_ = true;
    }
    feature.failed = true;
  }
  const bool as_error = is_error && !options_.skip_invalid;
  report(as_error ? base::Severity::kError : base::Severity::kWarning, code,
         feature_label(index) + ": " + message, where, std::move(notes));
}

std::string FootprintBuilder::polygon_label(std::size_t index, std::size_t p) const {
  return features_[index].multi ? "polygon " + std::to_string(p) : std::string("polygon");
}

// Longitude/latitude without a named CRS gives itself away: degrees when every polygon lies within
// +-180 x +-90 and most span less than 0.05 units: no building is 5 cm wide, but a map export's
// landuse, forest or boundary polygons beside its buildings span more than 0.05 degrees, and one of
// them must not turn the city into meters. A hand-made file in meters near (0, 0) stays in meters.
// Map areas (map_areas_) vote only when no other polygon does: `check` reads them too, and must
// decide as `mass` does.
bool FootprintBuilder::looks_like_degrees() const {
  const std::optional<bool> buildings = degrees_vote(false);
  return buildings ? *buildings : degrees_vote(true).value_or(false);
}

// The vote of looks_like_degrees(), with or without the map areas; nullopt when no polygon votes.
std::optional<bool> FootprintBuilder::degrees_vote(bool map_areas) const {
  std::size_t polygons = 0, small = 0;
  for (std::size_t f = 0; f < features_.size(); ++f) {
    const RawFootprint& feature = features_[f];
    if (feature.failed || (!map_areas && !map_areas_.empty() && map_areas_[f])) continue;
    for (const kernel::Polygon& polygon : feature.polygons) {
      const kernel::Bounds2 box = kernel::bounds(polygon);
      const bool in_range = std::abs(box.min.x) <= 180 && std::abs(box.max.x) <= 180 &&
                            std::abs(box.min.y) <= 90 && std::abs(box.max.y) <= 90;
      if (!in_range) return false;
      ++polygons;
      small += box.max.x - box.min.x < 0.05 && box.max.y - box.min.y < 0.05;
    }
  }
  if (polygons == 0) return std::nullopt;
  return 2 * small > polygons;
}

// The CRS step (docs/geojson.md, "Coordinates, units and CRS"). The input CRS is the one the
// input names, else --crs, else longitude/latitude when the coordinates look like degrees. The
// CRS to build in is --out-crs, else (the older meaning of --crs) a ground-metric --crs the input
// was not declared in, else the input CRS when it is in ground meters, else the UTM zone of the
// data's centre: degrees, feet and Web Mercator's inflated meters are reprojected.
void FootprintBuilder::resolve_crs(const Location& crs_at) {
  std::string error;
  const std::string& given = options_.crs;
  std::string target = options_.out_crs;
  if (!target.empty()) {
    if (const std::string why = buildable_crs(target); !why.empty()) {
      report(base::Severity::kError, "GEO007", options_name_ + "::out_crs: " + why, whole_input());
      return;
    }
  }
  std::optional<CrsInfo> given_info;
  if (!given.empty()) {
    given_info = describe_crs(given, error);
    if (!given_info) {
      report(base::Severity::kError, "GEO007", options_name_ + "::crs: " + given + ": " + error,
             whole_input());
      return;
    }
  }
  const bool given_buildable = given_info && given_info->metric;
  std::string source = declared_crs_;
  if (source.empty()) {
    const bool degrees = looks_like_degrees();
    if (given_info && !(degrees && given_buildable)) {
      source = given_info->name;  // --crs states the CRS of input that names none
    } else if (degrees) {
      source = "OGC:CRS84";  // RFC 7946: GeoJSON without a "crs" member is WGS 84 lon/lat
    } else {
      result_.crs = target;  // meters in no named CRS: in the one asked for, if any
      return;
    }
  }
  if (target.empty() && given_buildable && source != given_info->name) target = given_info->name;
  if (!declared_crs_.empty() && given_info && !given_buildable) {
    report(base::Severity::kWarning, "GEO007",
           options_name_ + "::crs " + given_info->name + " ignored: the input names its CRS (" +
               declared_crs_ + ")",
           crs_at);
  }
  const std::optional<CrsInfo> info = describe_crs(source, error);
  if (!info) {
    if (target.empty()) {
      report(base::Severity::kWarning, "GEO007",
             "crs " + source + ": " + error + "; coordinates taken as meters", crs_at);
      result_.crs = source;
    } else {
      report(base::Severity::kError, "GEO007",
             "crs " + source + ": " + error + "; cannot reproject to " + target, crs_at);
    }
    return;
  }
  if (info->geographic) to_geographic_range();
  if (errors_ > 0) return;
  if (target.empty() && info->metric) {
    result_.crs = info->name;
    return;
  }
  if (target.empty()) {
    kernel::Bounds2 box = valid_bounds();
    if (box.empty()) return;
    if (!info->geographic) {
      // Feet, Web Mercator: the UTM zone of the data's centre, found in longitude/latitude.
      std::vector<kernel::Vec2> centre{(box.min + box.max) * 0.5};
      if (const std::string why = io::reproject(info->name, "OGC:CRS84", centre); !why.empty()) {
        report(base::Severity::kError, "GEO007", why, crs_at);
        return;
      }
      box = kernel::Bounds2{};
      box.add(centre[0]);
    }
    target = utm_crs(info->geographic ? centre_longitude(box) : box.min.x,
                     0.5 * (box.min.y + box.max.y));
  }
  const std::optional<CrsInfo> to = describe_crs(target, error);
  if (to && to->name == info->name) {
    result_.crs = info->name;
    return;
  }
  reproject_all(info->name, to ? to->name : target, crs_at);
}

// Degrees in a geographic CRS: a coordinate beyond +-180 x +-90 says the input's CRS is wrong
// (often meters under an EPSG:4326 label); guessing would misplace the building.
void FootprintBuilder::to_geographic_range() {
  for (std::size_t f = 0; f < features_.size(); ++f) {
    RawFootprint& feature = features_[f];
    if (feature.failed) continue;
    for (std::size_t p = 0; p < feature.polygons.size() && !feature.failed; ++p) {
      const kernel::Polygon& polygon = feature.polygons[p];
      for (std::size_t r = 0; r <= polygon.holes.size() && !feature.failed; ++r) {
        const kernel::Ring& ring = r == 0 ? polygon.outer : polygon.holes[r - 1];
        for (std::size_t i = 0; i < ring.size(); ++i) {
          if (std::abs(ring[i].x) <= 180 && std::abs(ring[i].y) <= 90) continue;
          const std::string crs = declared_crs_.empty() ? options_.crs : declared_crs_;
          feature_issue(f, true, "GEO008",
                        polygon_label(f, p) + " ring " + std::to_string(r) + " position " +
                            std::to_string(i) + " " + point_text(ring[i]) +
                            " is not a longitude/latitude, but crs " + crs +
                            " is geographic (degrees)",
                        locate(f, {feature.multi ? p : kNoIndex, r, i}));
          break;
        }
      }
    }
  }
}

void FootprintBuilder::reproject_all(const std::string& from, const std::string& to,
                                     const Location& crs_at) {
  std::vector<kernel::Vec2> points;
  for (const RawFootprint& feature : features_) {
    if (feature.failed) continue;
    for (const kernel::Polygon& polygon : feature.polygons) {
      points.insert(points.end(), polygon.outer.begin(), polygon.outer.end());
      for (const kernel::Ring& hole : polygon.holes) {
        points.insert(points.end(), hole.begin(), hole.end());
      }
    }
  }
  if (const std::string error = io::reproject(from, to, points); !error.empty()) {
    report(base::Severity::kError, "GEO007", error, crs_at);
    return;
  }
  std::size_t next = 0;
  for (std::size_t f = 0; f < features_.size(); ++f) {
    RawFootprint& feature = features_[f];
    if (feature.failed) continue;
    for (std::size_t p = 0; p < feature.polygons.size(); ++p) {
      kernel::Polygon& polygon = feature.polygons[p];
      for (std::size_t r = 0; r <= polygon.holes.size(); ++r) {
        kernel::Ring& ring = r == 0 ? polygon.outer : polygon.holes[r - 1];
        for (std::size_t i = 0; i < ring.size(); ++i) {
          const kernel::Vec2 q = points[next++];
          if (std::isfinite(q.x) && std::isfinite(q.y)) {
            ring[i] = q;
          } else if (!feature.failed) {
            feature_issue(f, true, "GEO008",
                          polygon_label(f, p) + " ring " + std::to_string(r) + " position " +
                              std::to_string(i) + " could not be reprojected from " + from +
                              " to " + to,
                          locate(f, {feature.multi ? p : kNoIndex, r, i}));
          }
        }
      }
    }
  }
  result_.crs = to;
  result_.source_crs = from;
}

// The bounding box of the features still valid, in world coordinates.
kernel::Bounds2 FootprintBuilder::valid_bounds() const {
  kernel::Bounds2 box;
  for (const RawFootprint& feature : features_) {
    if (feature.failed) continue;
    for (const kernel::Polygon& polygon : feature.polygons) {
      const kernel::Bounds2 b = kernel::bounds(polygon);
      box.add(b.min);
      box.add(b.max);
    }
  }
  return box;
}

// The longitude in the middle of the data (degrees): the box's centre, unless the data straddles
// the antimeridian (a box wider than half the globe), whose centre lies on the far side of the
// Earth: a town in Fiji got UTM zone 31, 177 degrees from its central meridian. Then the middle
// of the gap-free span from the least eastern longitude to the greatest western one.
double FootprintBuilder::centre_longitude(const kernel::Bounds2& box) const {
  if (box.max.x - box.min.x <= 180) return 0.5 * (box.min.x + box.max.x);
  double east_start = 180;  // the least longitude >= 0
  double west_end = -180;   // the greatest longitude < 0
  for (const RawFootprint& feature : features_) {
    if (feature.failed) continue;
    for (const kernel::Polygon& polygon : feature.polygons) {
      for (const kernel::Vec2& p : polygon.outer) {
        if (p.x >= 0) {
          east_start = std::min(east_start, p.x);
        } else {
          west_end = std::max(west_end, p.x);
        }
      }
    }
  }
  return 0.5 * (east_start + west_end + 360);
}

// The bounding-box centre rounded down to whole meters: local coordinates stay within half the
// data's extent (which float32 outputs such as glTF need), and world - origin is exact whenever
// origin and world lie within a factor of 2 of each other (Sterbenz), which holds for any dataset
// smaller than its distance from (0, 0): UTM tiles, national grids.
void FootprintBuilder::choose_origin() {
  const kernel::Bounds2 box = valid_bounds();
  if (options_.origin) {
    result_.origin = {options_.origin->x, options_.origin->y, 0};
  } else if (!box.empty() &&
             (std::max(std::abs(box.min.x), std::abs(box.max.x)) > options_.shift_threshold ||
              std::max(std::abs(box.min.y), std::abs(box.max.y)) > options_.shift_threshold)) {
    result_.origin = {std::floor(0.5 * box.min.x + 0.5 * box.max.x),
                      std::floor(0.5 * box.min.y + 0.5 * box.max.y), 0};
  }
}

// A repair of `kind`: counted always, warned about the first time in a read (with its count
// in this polygon), so a city of messy rings gives one line per kind rather than thousands.
void FootprintBuilder::note_repair(std::size_t index, std::size_t p, const char* kind,
                                   const char* code, const std::string& message,
                                   const FootprintPlace& place, std::size_t count) {
  result_.repairs[kind] += count;
  bool& warned = warned_repair_[kind];
  if (warned) return;
  warned = true;
  std::string text = polygon_label(index, p) + ": " + message;
  if (count > 1) text += " (and " + std::to_string(count - 1) + " more like it)";
  std::vector<std::string> notes = local_note();
  notes.push_back("later repairs of this kind are counted, not listed (the report's \"repairs\")");
  feature_issue(index, false, code, text, locate(index, place), std::move(notes));
}

// Repair in local coordinates (small numbers keep the kernel's tolerance meaningful). A ring that
// passes twice through one point is split there first (kernel::split_touching_rings); each piece
// is then repaired. Orientation fixes are silent: either winding is accepted.
void FootprintBuilder::repair(std::size_t index, Footprint& footprint) {
  RawFootprint& feature = features_[index];
  const kernel::Vec2 origin{result_.origin.x, result_.origin.y};
  for (std::size_t p = 0; p < feature.polygons.size() && !feature.failed; ++p) {
    kernel::Polygon& polygon = feature.polygons[p];
    for (kernel::Vec2& v : polygon.outer) v -= origin;
    for (kernel::Ring& hole : polygon.holes) {
      for (kernel::Vec2& v : hole) v -= origin;
    }
    kernel::TouchSplit split = kernel::split_touching_rings(polygon);
    if (!split.points.empty()) {
      std::size_t holes_before = polygon.holes.size(), holes_after = 0;
      for (const kernel::Polygon& piece : split.polygons) holes_after += piece.holes.size();
      std::string message = "a ring passes twice through " + point_text(split.points[0]) +
                            "; split there into " + std::to_string(split.polygons.size()) +
                            (split.polygons.size() == 1 ? " polygon" : " polygons");
      if (holes_after > holes_before) {
        message += " and " + std::to_string(holes_after - holes_before) +
                   (holes_after - holes_before == 1 ? " hole" : " holes");
      }
      FootprintPlace place{features_[index].multi ? p : kNoIndex, 0, kNoIndex};
      nearest_position(polygon, split.points[0], 0, place);
      note_repair(index, p, "split_touching_ring", "GEO027", message, place, split.points.size());
    }
    for (kernel::Polygon& piece : split.polygons) {
      if (feature.failed) break;
      repair_piece(index, p, std::move(piece), footprint);
    }
  }
  if (!feature.failed && footprint.polygons.empty() && feature.polygons.size() > 1) {
    feature_issue(index, true, "GEO028",
                  "feature " + std::to_string(index) + ": every polygon is a sliver",
                  locate(index, {kNoIndex, kNoIndex, kNoIndex}), local_note());
  }
}

void FootprintBuilder::repair_piece(std::size_t index, std::size_t p, kernel::Polygon piece,
                                    Footprint& footprint) {
  RawFootprint& feature = features_[index];
  const kernel::Polygon& written = feature.polygons[p];
  const std::size_t where_p = feature.multi ? p : kNoIndex;
  kernel::RepairResult repaired = kernel::repair(piece, options_.repair_tolerance);
  std::map<kernel::PolygonIssueKind, std::size_t> repeats;
  for (const kernel::PolygonIssue& issue : repaired.issues) {
    if (issue.repaired) ++repeats[issue.kind];
  }
  for (const kernel::PolygonIssue& issue : repaired.issues) {
    // Orientation is free in GeoJSON and OSM; repairs of a rejected polygon are noise.
    if (issue.kind == kernel::PolygonIssueKind::kWrongOrientation) continue;
    if (issue.repaired && !repaired.ok) continue;
    const FootprintPlace place{
        where_p, issue.ring >= 0 ? static_cast<std::size_t>(issue.ring) : kNoIndex,
        issue.vertex >= 0 ? static_cast<std::size_t>(issue.vertex) : kNoIndex};
    if (issue.repaired) {
      std::size_t& count = repeats[issue.kind];
      if (count == 0) continue;  // counted with the first of its kind
      note_repair(index, p, repair_kind(issue), repair_code(issue.kind), issue.message, place,
                  count);
      count = 0;
      continue;
    }
    const char* code = repair_code(issue.kind);
    std::string message = polygon_label(index, p) + ": " + issue.message;
    if (issue.kind == kernel::PolygonIssueKind::kTooFewVertices && issue.ring == 0 &&
        has_three_distinct(piece.outer)) {
      // Collinear and spike removal left too little: the ring was a line all along.
      code = "GEO021";
      message = polygon_label(index, p) + ": outer ring: zero area (its positions lie on one line)";
    }
    feature_issue(index, true, code, message, locate(index, place), local_note());
  }
  if (!repaired.ok) return;
  if (!kernel::is_simple_polygon(repaired.polygon)) {
    // Rings meeting at a point (valid OGC, but no skeleton): move the touching hole vertex a
    // little into its hole, so walls and roofs get a simple outline of the same shape.
    kernel::Polygon separated = repaired.polygon;
    const std::vector<kernel::Vec2> moved =
        kernel::separate_touching_rings(separated, options_.touch_separation);
    if (moved.empty() || !kernel::is_simple_polygon(separated)) {
      reject_touching_rings(index, p, repaired.polygon);
      return;
    }
    FootprintPlace place{where_p, kNoIndex, kNoIndex};
    nearest_position(written, moved[0], 1, place);
    note_repair(index, p, "separated_touching_rings", "GEO027",
                "rings touch at " + point_text(moved[0]) +
                    "; separated them by moving the touching vertex " +
                    number_text(options_.touch_separation) + " m",
                place, moved.size());
    repaired.polygon = std::move(separated);
  }
  const double area = kernel::area(repaired.polygon);
  const double width = 2 * area / kernel::perimeter(repaired.polygon);
  if (area < options_.min_area || width < options_.min_width) {
    // One sliver among a MultiPolygon's polygons (a 0.7 m2 scrap beside a register's 27 m2
    // building) is left out; the feature fails only when none is left (repair()).
    const bool others = feature.polygons.size() > 1;
    feature_issue(index, !others, "GEO028",
                  polygon_label(index, p) + ": a sliver (area " + rounded(area) +
                      " m2, width about " + rounded(width) + " m = 2 * area / perimeter; " +
                      "footprints need at least " + number_text(options_.min_area) + " m2 and " +
                      number_text(options_.min_width) + " m)" +
                      (others ? "; left out, the feature keeps its other polygons" : ""),
                  locate(index, {where_p, 0, kNoIndex}), local_note());
    return;
  }
  const kernel::Ring& outer = piece.outer.empty() ? written.outer : piece.outer;
  const auto second =
      std::find_if(outer.begin(), outer.end(), [&](kernel::Vec2 v) { return v != outer[0]; });
  footprint.first_edges.push_back({outer[0], second == outer.end() ? outer[0] : *second});
  footprint.outer_clockwise.push_back(kernel::signed_area(outer) < 0);
  footprint.polygons.push_back(std::move(repaired.polygon));
}

std::vector<std::string> FootprintBuilder::local_note() const {
  if (result_.origin.x == 0 && result_.origin.y == 0) return {};
  return {"coordinates in this message are local: world = local + (" +
          number_text(result_.origin.x) + ", " + number_text(result_.origin.y) + ")"};
}

// Rings that touch where no repair applies: rejected here, so that `check` and every builder
// agree, with where they touch.
void FootprintBuilder::reject_touching_rings(std::size_t index, std::size_t p,
                                             const kernel::Polygon& repaired) {
  RawFootprint& feature = features_[index];
  std::string message = polygon_label(index, p) + ": ";
  FootprintPlace where{feature.multi ? p : kNoIndex, kNoIndex, kNoIndex};
  if (const std::optional<Touch> touch = find_touch(repaired)) {
    const auto name = [](std::size_t ring) {
      return ring == 0 ? std::string("the outer ring") : "hole " + std::to_string(ring);
    };
    message += touch->ring_a == touch->ring_b
                   ? name(touch->ring_a) + " touches itself"
                   : name(touch->ring_b) + " touches " + name(touch->ring_a);
    message += " at " + point_text(touch->point);
    nearest_position(feature.polygons[p], touch->point, touch->ring_b, where);
  } else {
    message += "rings touch or fold back on themselves";
  }
  message += "; footprint rings must not meet (walls and roofs need a simple outline)";
  feature_issue(index, true, "GEO027", message, locate(index, where), local_note());
}

// Whether no two footprints have the same id: then none is renamed, and a city needs no sets of
// its ids (a million of them cost about 200 MB at the reader's peak).
bool FootprintBuilder::ids_distinct() const {
  std::unordered_set<std::string_view> seen;
  seen.reserve(result_.footprints.size());
  for (const Footprint& footprint : result_.footprints) {
    if (!seen.insert(footprint.id).second) return false;
  }
  return true;
}

// Each footprint's own id, or its fallback; renamed where ids repeat.
void FootprintBuilder::assign_ids() {
  for (Footprint& footprint : result_.footprints) {
    const std::size_t index = footprint.feature_index;
    std::string& id = features_[index].id;
    if (!options_.id_property.empty()) {
      const std::optional<shape::Value> named = footprint.properties.find(options_.id_property);
      if (named && !shape::is_null(*named) && !shape::to_string(*named).empty()) {
        id = shape::to_string(*named);
      }
    }
    footprint.id = id.empty() ? fallback_id(index) : id;
  }
  if (!ids_distinct()) assign_ids_renaming();
}

// Input order decides: the first feature keeps an id, later ones are renamed.
void FootprintBuilder::assign_ids_renaming() {
  std::set<std::string, std::less<>> used;
  for (const RawFootprint& feature : features_) {
    if (!feature.id.empty()) used.insert(feature.id);
  }
  std::set<std::string, std::less<>> taken;
  std::map<std::string, std::size_t, std::less<>> first_user;
  base::NumberedNames numbered("-");
  for (Footprint& footprint : result_.footprints) {
    const std::size_t index = footprint.feature_index;
    std::string id = std::move(footprint.id);
    if (taken.count(id) != 0) {
      // `id` itself is taken, so the first free name is numbered; an input id is never free.
      const std::string renamed = numbered.next(id, [&](const std::string& name) {
        return taken.count(name) == 0 && used.count(name) == 0;
      });
      FootprintPlace place;
      place.id = true;
      feature_issue(index, false, "GEO019",
                    "id " + quote_text(id) + " is already used by " + feature_name(first_user[id]) +
                        "; renamed to " + quote_text(renamed),
                    locate(index, place));
      id = renamed;
    }
    first_user.emplace(id, index);
    taken.insert(id);
    footprint.id = std::move(id);
  }
}

RawFootprint& FootprintBuilder::add_raw() {
  properties_.add_row();
  return features_.emplace_back();
}

// While reading, a feature error of what may be a map area (its properties are read before its
// geometry) waits for the whole file: a map export's landuse polygon with a ring of 3 positions
// fails nothing. The feature takes no polygons meanwhile, as a failed one.
bool FootprintBuilder::hold_issue(std::size_t index, const char* code, const std::string& message,
                                  const Location& where, std::vector<std::string>& notes) {
  if (!holding_ || !options_.leave_out_non_buildings) return false;
  // A non-owning pointer to the table being filled: the row lives only for this call.
  const std::shared_ptr<const PropertyTable> table(std::shared_ptr<const PropertyTable>(),
                                                   &properties_);
  if (!non_building_area(PropertyRow(table, index))) return false;
  held_.push_back({index, code, message, where, std::move(notes)});
  features_[index].failed = true;
  return true;
}

// Only a map export, where buildings carry their tag, has map areas: a register whose text column
// happens to be called `landuse` or `amenity` keeps every footprint.
bool FootprintBuilder::map_export(const std::shared_ptr<const PropertyTable>& properties) const {
  for (std::size_t i = 0; i < features_.size(); ++i) {
    if (tagged_building(PropertyRow(properties, i))) return true;
  }
  return false;
}

// The held errors: a map export's map area is left out with them (find_map_areas(), which
// map_areas_ tells); anywhere else they are reported as if never held. A feature's held errors
// are consecutive (it is read whole).
void FootprintBuilder::release_held(const std::shared_ptr<const PropertyTable>& properties,
                                    bool map_export) {
  holding_ = false;
  if (map_export) map_areas_.assign(features_.size(), false);
  std::vector<HeldIssue> held;
  held.swap(held_);
  bool area = false;
  for (std::size_t k = 0; k < held.size(); ++k) {
    HeldIssue& issue = held[k];
    // A reader that forgets what it read (GeoJSON's syntax error) forgets these errors too.
    if (issue.index >= features_.size()) continue;
    if (k == 0 || held[k - 1].index != issue.index) {
      features_[issue.index].failed = false;
      // Its properties were whole when it was held (a reader reads them before the geometry).
      area = map_export && non_building_area(PropertyRow(properties, issue.index));
      if (area) map_areas_[issue.index] = true;
    }
    if (area) continue;
    feature_issue(issue.index, true, issue.code.c_str(), issue.message, issue.where,
                  std::move(issue.notes));
  }
}

// Which features of a map export are map areas (map_areas_), before the CRS step; under
// leave_out_non_buildings they lose their polygons, so they widen no bounding box and are never
// repaired or checked.
void FootprintBuilder::find_map_areas(const std::shared_ptr<const PropertyTable>& properties) {
  for (std::size_t i = 0; i < features_.size(); ++i) {
    const RawFootprint& feature = features_[i];
    const bool held = map_areas_[i];
    if (!held && (feature.failed || feature.polygons.empty())) continue;
    std::optional<std::string> tag = non_building_area(PropertyRow(properties, i));
    if (!tag) continue;
    map_areas_[i] = true;
    if (options_.leave_out_non_buildings) leave_out_map_area(i, std::move(*tag));
  }
}

void FootprintBuilder::leave_out_map_area(std::size_t index, std::string tag) {
  std::vector<kernel::Polygon>().swap(features_[index].polygons);
  ++result_.non_buildings;
  if (area_tags_.insert(tag).second) result_.non_building_tags.push_back(std::move(tag));
}

// GEO006's note: why no footprint is left. Map areas are left out without a warning each, so
// the note names them.
std::string FootprintBuilder::nothing_left_note() const {
  if (features_.empty() && !empty_note_.empty()) return empty_note_;
  std::string note = std::to_string(features_.size()) + " feature" +
                     (features_.size() == 1 ? "" : "s") +
                     " read; the warnings above say why each was skipped";
  if (result_.non_buildings > 0) {
    note += "; " + std::to_string(result_.non_buildings) + " map area" +
            (result_.non_buildings == 1 ? "" : "s") + " that " +
            (result_.non_buildings == 1 ? "is" : "are") + " not a building left out (" +
            result_.non_building_tags[0] + (result_.non_building_tags.size() > 1 ? ", ..." : "") +
            ")";
  }
  return note;
}

void FootprintBuilder::finish_features(const Location& crs_at) {
  const auto properties = std::make_shared<const PropertyTable>(std::move(properties_));
  const bool tagged_export = map_export(properties);
  release_held(properties, tagged_export);
  if (errors_ == 0 && tagged_export) find_map_areas(properties);
  if (errors_ == 0) resolve_crs(crs_at);
  if (errors_ == 0) {
    choose_origin();
    result_.footprints.reserve(features_.size());
    for (std::size_t i = 0; i < features_.size(); ++i) {
      RawFootprint& feature = features_[i];
      if (feature.failed || feature.polygons.empty() || stopped_) continue;
      Footprint footprint;
      footprint.feature_index = i;
      repair(i, footprint);
      // The input rings are no longer needed: a country's worth of them would double the peak.
      std::vector<kernel::Polygon>().swap(feature.polygons);
      if (feature.failed) continue;
      footprint.properties = PropertyRow(properties, i);
      result_.footprints.push_back(std::move(footprint));
    }
  }
  if (errors_ == 0 && result_.footprints.empty()) {
    report(base::Severity::kError, "GEO006", "no polygon features", whole_input(),
           {nothing_left_note()});
  }
  if (errors_ == 0) assign_ids();
  result_.skipped_invalid = static_cast<std::size_t>(std::count_if(
      features_.begin(), features_.end(), [](const RawFootprint& f) { return f.failed; }));
}

// Diagnostics in input order (those without a position last), then a note per code of the
// warnings past max_warnings that were counted and not listed (FootprintSet::unlisted_warnings
// holds the same counts when the read succeeds).
base::Result<FootprintSet> FootprintBuilder::result() {
  std::stable_sort(pending_.begin(), pending_.end(),
                   [](const Pending& a, const Pending& b) { return a.order < b.order; });
  std::vector<base::Diagnostic> diagnostics;
  diagnostics.reserve(pending_.size() + result_.unlisted_warnings.size());
  for (Pending& p : pending_) diagnostics.push_back(std::move(p.diagnostic));
  for (const auto& [code, count] : result_.unlisted_warnings) {
    base::Diagnostic note = base::Diagnostic::warning(
        code,
        std::to_string(count) + " more warning" + (count == 1 ? "" : "s") +
            (code.empty() ? "" : " of this code") + " not listed",
        base::Span::whole(name_));
    note.severity = base::Severity::kNote;
    diagnostics.push_back(std::move(note));
  }
  if (errors_ > 0) return base::Result<FootprintSet>::failure(std::move(diagnostics));
  return base::Result<FootprintSet>(std::move(result_), std::move(diagnostics));
}

}  // namespace insula::io
