// The derivation loop, rule choice and the successor interpreter (seed 004 §II; derive.h), with
// CGA's built-ins that are not shape operations (color, set, print, report).
#include "lang/cga/derive_engine.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "base/css_colours.h"
#include "base/tag_numbers.h"
#include "lang/cga/colors.h"
#include "shape/query.h"
#include "shape/shape_tree.h"
#include "shape/uv_map.h"

namespace insula::lang::cga::detail {

void Engine::run() {
  try {
    start();
    loop();
    out_.ok = true;
    if (!keep_) {
      // Only terminal records read these: a count-only run (every lot's result kept until the
      // end) need not hold each lot's meshes meanwhile.
      out_.geometry = {};
      out_.attr_nodes = {};
    }
  } catch (const DeriveError& e) {
    out_.diagnostics.push_back(e.diagnostic);
  } catch (const EvalError& e) {
    base::Diagnostic d = base::Diagnostic::error("CGA603", e.message, program_.span(e.range));
    if (rule_ != nullptr) d.notes.push_back("in " + program_.describe(*rule_));
    d.notes.push_back("in lot '" + lot_.id + "'");
    out_.diagnostics.push_back(std::move(d));
  }
  flush_warnings();
}

Value Engine::attribute(std::uint32_t attr, Range range) {
  for (std::uint32_t n = cur_ != nullptr ? cur_->attrs : 0; n != 0; n = out_.attr_nodes[n].parent) {
    if (out_.attr_nodes[n].attr == attr) return out_.attr_nodes[n].value;
  }
  return lot_value(attr, range);
}

double Engine::shape_attribute(ShapeAttr a) {
  const State& s = *cur_;
  switch (a) {
    case ShapeAttr::kSx:
      return s.scope.size.x;
    case ShapeAttr::kSy:  // a lot's CityEngine y is its normal (State::lot_axes)
      return lot_axes(s) ? s.scope.size.z : s.scope.size.y;
    case ShapeAttr::kSz:
      return lot_axes(s) ? s.scope.size.y : s.scope.size.z;
    case ShapeAttr::kTx:
      return program_.cityengine ? object_position(s).x : s.scope.origin.x;
    case ShapeAttr::kTy:
      return program_.cityengine ? object_position(s).y : s.scope.origin.y;
    case ShapeAttr::kTz:
      return program_.cityengine ? object_position(s).z : s.scope.origin.z;
    case ShapeAttr::kArea: {
      const Geometry& g = out_.geometry[s.geometry];
      if (g.kind == Geometry::Kind::kMesh && g.outline) return g.area;
      return s.scope.size.x * s.scope.size.y;
    }
    case ShapeAttr::kVolume:
      return s.scope.volume();
    case ShapeAttr::kDepth:
      return depth_;
    case ShapeAttr::kIndex:
      return s.index;
    case ShapeAttr::kTotal:
      return s.total;
    case ShapeAttr::kElevation:
      return s.scope.origin.z;
    case ShapeAttr::kInitialPx:
      return start_state_.scope.origin.x;
    case ShapeAttr::kInitialPy:
      return start_state_.scope.origin.z;
    case ShapeAttr::kInitialPz:
      return -start_state_.scope.origin.y + 0.0;
    case ShapeAttr::kSeedian:  // a whole number as CityEngine's seeds are (its values differ)
      return static_cast<double>(s.seed & 0x7fffffffU);
  }
  return 0;
}

// CityEngine's scope.t: the origin in the object's coordinates, which are the initial shape's
// scope read as CityEngine reads a lot (x, its normal, −y). A lot's CityEngine origin is the
// corner where its z (Insula's −y) starts.
Vec3 Engine::object_position(const State& s) const {
  const auto ce_origin = [](const Scope& scope, bool lot) {
    return lot ? scope.origin + scope.y * scope.size.y : scope.origin;
  };
  const Scope& o = start_state_.scope;
  const bool flat = o.size.z == 0;
  const Vec3 d = ce_origin(s.scope, lot_axes(s)) - ce_origin(o, flat);
  const Vec3 t{dot(d, o.x), dot(d, flat ? o.z : o.y), dot(d, flat ? -o.y : o.z)};
  return t + Vec3{0, 0, 0};  // no -0 in print()
}

// CityEngine's set(scope.tx, v): the scope (and its geometry) moved along the object frame's
// axis so that scope.tx reads v (object_position's inverse).
void Engine::set_scope_translation(const CItem& c, State& st) {
  const double value = number(c.args[0], st);
  if (!std::isfinite(value)) {
    throw EvalError{program_.nodes[c.args[0]].range,
                    "the scope's translation must be a finite number, got " +
                        std::string(std::isnan(value) ? "NaN"
                                    : value > 0       ? "inf"
                                                      : "-inf")};
  }
  const Scope& o = start_state_.scope;
  const bool flat = o.size.z == 0;
  const std::array<Vec3, 3> axes = {o.x, flat ? o.z : o.y, flat ? o.y * -1.0 : o.z};
  const Vec3 t = object_position(st);
  const double now = c.attr == 0 ? t.x : c.attr == 1 ? t.y : t.z;
  st.scope.origin = st.scope.origin + axes[c.attr] * (value - now);
  touch(st);
}

double Engine::geometry(shape::GeometryQuery query, std::uint8_t option, double tolerance) {
  const State& s = *cur_;
  const Materialized m = materialize(out_.geometry[s.geometry], s.scope.size);
  if (!m.mesh) return 0;
  return shape::geometry_query(*m.mesh, s.scope, query, option, tolerance, context_.object,
                               m.outline.get());
}

std::string Engine::occlusion(const std::string& /*what*/, Range /*range*/) {
  // The configuration (seed 004 §II): every pending and terminal shape of this lot but the
  // asking one, as boxes (shape::occlusion's box approximation).
  const Scope& self = cur_->scope;
  const kernel::Bounds3 mine = bounds(self);
  shape::ShapeTree tree;
  const shape::ShapeId id = tree.add_root(self);
  std::vector<shape::ShapeId> others;
  const auto consider = [&](const Scope& s) {
    const kernel::Bounds3 b = bounds(s);
    constexpr double kTol = 1e-3;
    if (b.min.x > mine.max.x + kTol || b.max.x < mine.min.x - kTol || b.min.y > mine.max.y + kTol ||
        b.max.y < mine.min.y - kTol || b.min.z > mine.max.z + kTol || b.max.z < mine.min.z - kTol) {
      return;
    }
    others.push_back(tree.add_root(s));
  };
  for (std::size_t i = 0; i < out_.terminals_store.size(); ++i)
    consider(out_.terminals_store[i].scope);
  for (const auto& bucket : pending_) {
    for (const Work& w : bucket) {
      if (&w != current_) consider(w.scope);  // the asking shape's own record
    }
  }
  for (const Work& w : batch_) consider(w.scope);
  const double f = shape::occlusion(tree, id, others);
  return f <= 1e-6 ? "none" : f >= 1 - 1e-6 ? "full" : "part";
}

std::vector<std::uint64_t> Engine::lineage_seeds(std::uint32_t entry) const {
  std::vector<std::uint64_t> seeds;
  for (; entry != 0; entry = lineage_[entry].first) seeds.push_back(lineage_[entry].second);
  return seeds;
}

void Engine::add_occluder(const State& st, std::string label) {
  made_occluders_.push_back({std::move(label), st.scope, st.seed, lineage_seeds(st.lineage)});
}

namespace {

// The six faces of a box scope as flat scopes (a face's contact with another box is planar).
std::array<Scope, 6> box_faces(const Scope& s) {
  std::array<Scope, 6> faces;
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      Vec3 offset;
      Vec3 size = s.size;
      set_component(size, static_cast<shape::Axis>(axis), 0);
      if (side == 1)
        set_component(offset, static_cast<shape::Axis>(axis),
                      s.extent(static_cast<shape::Axis>(axis)));
      faces[static_cast<std::size_t>(axis * 2 + side)] = s.sub(offset, size);
    }
  }
  return faces;
}

// The fraction of `a`'s scope box that `b`'s covers (shape::occlusion's box approximation).
double covered(const Scope& a, const Scope& b) {
  shape::ShapeTree tree;
  const shape::ShapeId id = tree.add_root(a);
  return shape::occlusion(tree, id, {tree.add_root(b)});
}

}  // namespace

// CityEngine's inside / overlaps / touches, on scope boxes: against the previous pass's occluders
// with the label (any when ""), never the asking shape's own ancestors or descendants. Insula
// derives each lot on its own, so `inter` finds nothing (docs/cga-cityengine.md).
bool Engine::occlusion_query(OcclusionRelation relation, OcclusionTarget target,
                             const std::string& label) {
  if (occluders_ == nullptr || target == OcclusionTarget::kInter) return false;
  const State& self = *cur_;
  const std::vector<std::uint64_t> mine = lineage_seeds(self.lineage);
  constexpr double kEps = 1e-6;
  for (const Occluder& o : *occluders_) {
    if (!label.empty() && o.label != label) continue;
    if (std::find(mine.begin(), mine.end(), o.seed) != mine.end()) continue;  // an ancestor
    if (std::find(o.lineage.begin(), o.lineage.end(), self.seed) != o.lineage.end()) continue;
    const double f = covered(self.scope, o.scope);
    switch (relation) {
      case OcclusionRelation::kInside:
        if (f >= 1 - kEps) return true;
        break;
      case OcclusionRelation::kOverlaps:
        if (f > kEps || covered(o.scope, self.scope) > kEps) return true;
        break;
      case OcclusionRelation::kTouches: {
        // Overlap, or planar contact: a face of a flat shape (covered() counts boxes within a
        // millimetre of its plane), or a face of the box of a volume, covered in part.
        if (f > kEps) return true;
        const bool flat =
            self.scope.size.x <= 0 || self.scope.size.y <= 0 || self.scope.size.z <= 0;
        if (flat) break;
        for (const Scope& face : box_faces(self.scope)) {
          if (covered(face, o.scope) > kEps) return true;
        }
        break;
      }
      case OcclusionRelation::kMinimumDistance:
        break;  // a number: minimum_distance()
    }
  }
  return false;
}

namespace {

// The distance from `p` to the box of scope `s` (0 inside).
double distance_to_box(const Scope& s, Vec3 p) {
  const Vec3 local = s.to_local(p);
  const Vec3 nearest{std::clamp(local.x, 0.0, std::max(0.0, s.size.x)),
                     std::clamp(local.y, 0.0, std::max(0.0, s.size.y)),
                     std::clamp(local.z, 0.0, std::max(0.0, s.size.z))};
  return kernel::length(s.to_world(nearest) - p);
}

// Between two scope boxes: 0 when they overlap, else the least corner-to-box distance either way
// (exact for boxes facing each other across a face or a corner; two boxes whose nearest points
// both lie on edges get at most that edge-to-edge gap over-estimated).
double box_distance(const Scope& a, const Scope& b) {
  if (covered(a, b) > 0 || covered(b, a) > 0) return 0;
  double best = std::numeric_limits<double>::infinity();
  for (const Vec3& p : a.corners()) best = std::min(best, distance_to_box(b, p));
  for (const Vec3& p : b.corners()) best = std::min(best, distance_to_box(a, p));
  return best;
}

}  // namespace

// CityEngine's geometry.du .. vMax on the shape's uv set (shape/uv_map.h: an affine projection
// of the world positions); a shape without the set measures 0, as one without texture
// coordinates does in CityEngine.
std::optional<shape::UvMap> Engine::uv_map(const State& st, int set) const {
  const std::string name = shape::uv_set_attribute(set);
  const std::vector<Value> state = state_values(st);
  for (std::size_t k = 0; k < state.size(); ++k) {
    if (program_.attrs[program_.state_attrs[k]].name == name) {
      return shape::decode_uv_map(to_shape(state[k]));
    }
  }
  return std::nullopt;
}

double Engine::uv_extent(std::uint8_t which, int set, bool unit_space) {
  const std::optional<shape::UvMap> map = uv_map(*cur_, set);
  const Materialized m = materialize(out_.geometry[cur_->geometry], cur_->scope.size);
  if (!map || !m.mesh) return 0;
  std::vector<Vec3> points;
  for (const Vec3& p : m.mesh->positions()) points.push_back(cur_->scope.to_world(p));
  const std::optional<shape::UvRange> range = shape::uv_range(*map, points);
  if (!range) return 0;
  switch (which) {
    case 0:  // du: along u, in meters when unitSpace (u grows by |du| per meter)
      return (range->max.x - range->min.x) /
             (unit_space && length(map->du) > 0 ? length(map->du) : 1.0);
    case 1:
      return (range->max.y - range->min.y) /
             (unit_space && length(map->dv) > 0 ? length(map->dv) : 1.0);
    case 2:
      return range->min.x;
    case 3:
      return range->max.x;
    case 4:
      return range->min.y;
    default:
      return range->max.y;
  }
}

// CityEngine's getGeoCoord: the scope origin in the scene CRS (the lots' local meters plus their
// origin), or in WGS 84 through the scene's CRS.
double Engine::geo_coord(const std::string& which, Range range) {
  const kernel::Vec3 local = cur_->scope.origin;
  const kernel::Vec3 origin = options_.geo != nullptr ? options_.geo->origin : kernel::Vec3{};
  const kernel::Vec2 xy{origin.x + local.x, origin.y + local.y};
  if (which == "x") return xy.x;
  if (which == "y") return xy.y;
  if (which != "lon" && which != "lat") {
    throw EvalError{range, "getGeoCoord takes x, y, lon or lat, got '" + which + "'"};
  }
  const std::optional<kernel::Vec2> ll =
      options_.geo != nullptr ? options_.geo->lon_lat(xy) : std::nullopt;
  if (!ll) {
    throw EvalError{range, "getGeoCoord(" + which +
                               ") needs the lots' coordinate system (a projected GeoJSON, or "
                               "lon/lat lots, which Insula projects)"};
  }
  return which == "lon" ? ll->x : ll->y;
}

// Against the previous pass's occluders as occlusion_query, on scope boxes.
double Engine::minimum_distance(OcclusionTarget target, const std::string& label) {
  double best = std::numeric_limits<double>::infinity();
  if (occluders_ == nullptr || target == OcclusionTarget::kInter) return best;
  const State& self = *cur_;
  const std::vector<std::uint64_t> mine = lineage_seeds(self.lineage);
  for (const Occluder& o : *occluders_) {
    if (!label.empty() && o.label != label) continue;
    if (std::find(mine.begin(), mine.end(), o.seed) != mine.end()) continue;  // an ancestor
    if (std::find(o.lineage.begin(), o.lineage.end(), self.seed) != o.lineage.end()) continue;
    best = std::min(best, box_distance(self.scope, o.scope));
  }
  return best;
}

// CityEngine's imagesSortRatio(list, axes): the images of a string list, nearest first in
// width / height to the scope's size along the first axis over the second (in log scale);
// imageBestRatio(query, axes) is the first of the images a search finds.
std::string Engine::images_by_ratio(const std::string& list, const std::string& axes, Range range) {
  if (axes.size() != 2 || axes.find_first_not_of("xyz") != std::string::npos) {
    throw EvalError{range,
                    "the axes of an image ratio are two of x, y, z (\"yx\"), got '" + axes + "'"};
  }
  const auto size = [&](char c) {
    return shape_attribute(c == 'x' ? ShapeAttr::kSx : c == 'y' ? ShapeAttr::kSy : ShapeAttr::kSz);
  };
  const double want = std::log(std::max(size(axes[0]), 1e-9) / std::max(size(axes[1]), 1e-9));
  std::vector<std::pair<double, std::string>> ranked;
  std::string error;
  for (std::size_t begin = 0; begin < list.size();) {
    std::size_t end = list.find(';', begin);
    if (end == std::string::npos) end = list.size();
    std::string image = list.substr(begin, end - begin);
    begin = end + 1;
    const std::optional<double> w = options_.files->image_info(image, "sx", error);
    const std::optional<double> h = options_.files->image_info(image, "sy", error);
    if (image.empty() || !w || !h || !(*w > 0) || !(*h > 0)) continue;
    ranked.emplace_back(std::fabs(std::log(*w / *h) - want), std::move(image));
  }
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::string out;
  for (const auto& entry : ranked) out.append(entry.second).append(";");
  return out;
}

namespace {

// The items of a ';'-terminated string list, or of a string[] (`array` then says so).
std::vector<std::string> list_or_array(const Value& v, bool& array) {
  std::vector<std::string> items;
  if (const ArrayPtr* a = std::get_if<ArrayPtr>(&v)) {
    array = true;
    for (const shape::Value& item : (*a)->items) items.push_back(shape::to_string(item));
    return items;
  }
  array = false;
  const std::string list = as_text(v);
  for (std::size_t begin = 0; begin < list.size();) {
    const std::size_t end = std::min(list.find(';', begin), list.size());
    if (end > begin) items.push_back(list.substr(begin, end - begin));
    begin = end + 1;
  }
  return items;
}

Value list_or_array_value(const std::vector<std::string>& items, bool array) {
  if (array) {
    auto out = std::make_shared<Array>();
    out->type = ElementType::kString;
    out->rows = items.empty() ? 0 : 1;
    out->columns = items.size();
    out->items.assign(items.begin(), items.end());
    return ArrayPtr(std::move(out));
  }
  std::string out;
  for (const std::string& item : items) out.append(item).append(";");
  return out;
}

}  // namespace

// CityEngine's assetsSortSize(list, axes, maxScaleError) (ratio false) and assetsSortRatio(list,
// axes) (ratio true): the assets, best first. Per selected axis the scaling the asset needs to
// take the scope's extent is d = ln(scope / asset). By size an asset ranks by its largest |d|
// (then by the sum of |d|); by ratio by max(d) - min(d), the uniform scaling that fails to fit
// (for two axes |ln(asset ratio) - ln(scope ratio)|). An axis where the scope's extent is 0 does
// not count (i() keeps the asset's size there); an asset flat along a counted axis never fits.
// max_error > 0 keeps only assets whose scalings are all within 1 +- max_error.
// Assets whose size is unknown (missing files) are left out; ties keep the list's order.
std::vector<std::string> Engine::assets_sorted(std::vector<std::string> assets,
                                               const std::string& axes, bool ratio,
                                               double max_error, Range range) {
  const std::size_t least = ratio ? 2 : 1;
  bool valid = axes.size() >= least && axes.size() <= 3 &&
               axes.find_first_not_of("xyz") == std::string::npos;
  for (std::size_t i = 0; valid && i < axes.size(); ++i) {
    valid = axes.find(axes[i], i + 1) == std::string::npos;
  }
  if (!valid) {
    const char* expected = ratio ? "two or three of x, y, z (\"xz\", \"xyz\")"
                                 : "one to three of x, y, z (\"x\", \"xz\", \"xyz\")";
    throw EvalError{range, std::string("the axes of an asset ") + (ratio ? "ratio" : "size") +
                               " are " + expected + ", got '" + axes + "'"};
  }
  constexpr double kTiny = 1e-9;
  constexpr double kNever = std::numeric_limits<double>::infinity();
  struct Ranked {
    double score;
    double total;
    std::string asset;
  };
  std::vector<Ranked> ranked;
  std::string error;
  for (std::string& asset : assets) {
    double low = 0;
    double high = 0;
    double largest = 0;
    double total = 0;
    bool first = true;
    bool fits = true;
    bool known = true;
    for (const char c : axes) {
      const std::string key = std::string("s") + c;
      const std::optional<double> extent = options_.files->asset_info(asset, key, error);
      if (!extent || !std::isfinite(*extent)) {
        known = false;
        break;
      }
      const double scope = std::fabs(shape_attribute(c == 'x'   ? ShapeAttr::kSx
                                                     : c == 'y' ? ShapeAttr::kSy
                                                                : ShapeAttr::kSz));
      const double size = std::fabs(*extent);
      if (scope < kTiny) continue;  // as i(): a zero scope size takes the asset's
      if (size < kTiny) {
        largest = total = kNever;
        low = 0;
        high = kNever;
        fits = false;
        break;
      }
      const double d = std::log(scope / size);
      low = first ? d : std::min(low, d);
      high = first ? d : std::max(high, d);
      first = false;
      largest = std::max(largest, std::fabs(d));
      total += std::fabs(d);
      const double scale = scope / size;
      if (max_error > 0 && std::fabs(scale - 1) > max_error + 1e-12) fits = false;
    }
    if (!known) continue;
    if (max_error > 0 && !fits) continue;
    ranked.push_back(ratio ? Ranked{high - low, 0, std::move(asset)}
                           : Ranked{largest, total, std::move(asset)});
  }
  std::stable_sort(ranked.begin(), ranked.end(), [](const Ranked& a, const Ranked& b) {
    return a.score < b.score || (a.score == b.score && a.total < b.total);
  });
  std::vector<std::string> out;
  out.reserve(ranked.size());
  for (Ranked& entry : ranked) out.push_back(std::move(entry.asset));
  return out;
}

Value Engine::file_function(Function f, const std::vector<Value>& args, Range range) {
  const FileQueries* files = options_.files;
  const std::string first = as_text(args[0]);
  if (files == nullptr) throw EvalError{range, "file functions need files (none given)"};
  std::string error;
  std::optional<double> number;
  switch (f) {
    case Function::kAssetsSortSize:
    case Function::kAssetsSortRatio: {
      bool array = false;
      std::vector<std::string> assets = list_or_array(args[0], array);
      const bool ratio = f == Function::kAssetsSortRatio;
      const double max_error = ratio ? 0.0 : as_number(args[2], range);
      return list_or_array_value(
          assets_sorted(std::move(assets), as_text(args[1]), ratio, max_error, range), array);
    }
    case Function::kAssetBestSize:
    case Function::kAssetBestRatio:
    case Function::kAssetApproxSize:
    case Function::kAssetApproxRatio:
    case Function::kAssetFitSize: {
      // CityEngine's ce.lib: listFirst / listRandom(listRange(.., 0, n)) / listRandom of the
      // sorted search, so a pick draws from the generator only when there is a candidate.
      const std::string found = files->search(first, error);
      if (!error.empty()) throw EvalError{range, error};
      bool array = false;
      const bool ratio = f == Function::kAssetBestRatio || f == Function::kAssetApproxRatio;
      const double max_error = f == Function::kAssetFitSize ? as_number(args[2], range) : 0.0;
      const std::vector<std::string> sorted =
          assets_sorted(list_or_array(found, array), as_text(args[1]), ratio, max_error, range);
      if (sorted.empty()) return std::string();
      if (f == Function::kAssetBestSize || f == Function::kAssetBestRatio) return sorted.front();
      std::size_t count = sorted.size();
      if (f != Function::kAssetFitSize) {
        const double n = as_number(args[2], range);  // n < 1 (or NaN): the best one
        count = !(n >= 1)                                 ? 1
                : n >= static_cast<double>(sorted.size()) ? sorted.size()
                                                          : static_cast<std::size_t>(std::floor(n));
      }
      return sorted[std::min(count - 1,
                             static_cast<std::size_t>(rng_.unit() * static_cast<double>(count)))];
    }
    case Function::kReadStringTable:
    case Function::kReadFloatTable: {
      const std::optional<std::string> text = files->read_text(first, error);
      if (text) return read_table(*text, f == Function::kReadFloatTable);
      if (files->exists(first)) throw EvalError{range, error};
      // A missing file loses detail, as a missing asset does: a warning, and the model is made.
      warning(range, "'" + first + "' not found: an empty table");
      return read_table(std::string(), f == Function::kReadFloatTable);
    }
    case Function::kFileExists:
      return files->exists(first);
    case Function::kFileSearch: {
      std::string list = files->search(first, error);
      if (!error.empty()) throw EvalError{range, error};
      return list;
    }
    case Function::kImageBestRatio: {
      const std::string found = files->search(first, error);
      if (!error.empty()) throw EvalError{range, error};
      const std::string sorted = images_by_ratio(found, as_text(args[1]), range);
      return sorted.substr(0, sorted.find(';'));
    }
    case Function::kImagesSortRatio:
      return images_by_ratio(first, as_text(args[1]), range);
    case Function::kFileRandom: {
      std::string pick = files->random(first, rng_.unit(), error);
      if (!error.empty()) throw EvalError{range, error};
      return pick;
    }
    case Function::kAssetInfo:
      number = files->asset_info(first, as_text(args[1]), error);
      break;
    default:
      number = files->image_info(first, as_text(args[1]), error);
      break;
  }
  if (number) return *number;
  if (files->exists(first)) throw EvalError{range, error};
  warning(range, "'" + first + "' not found: 0");
  return 0.0;
}

namespace {

std::optional<Value> number_from_text(const std::string& text) {
  double number = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
  if (error != std::errc{} || end != text.data() + text.size() || !std::isfinite(number)) {
    return std::nullopt;
  }
  return Value{number};
}

}  // namespace

// The lot's property for attr `name`: the one of that name, else (when none) the first whose name
// written as an identifier is `name`; null values count as absent.
const shape::Value* Engine::lot_property(const std::string& name) const {
  if (auto it = lot_.properties.find(name); it != lot_.properties.end()) {
    return shape::is_null(it->second) ? nullptr : &it->second;
  }
  for (const auto& [property, value] : lot_.properties) {
    if (!shape::is_null(value) && base::spells_identifier(property, name)) return &value;
  }
  return nullptr;
}

Value Engine::lot_value(std::uint32_t attr, Range range) {
  if (status_[attr] == 2) return values_[attr];
  const CAttr& a = program_.attrs[attr];
  if (status_[attr] == 1) throw EvalError{range, "attribute '" + a.name + "' depends on itself"};
  status_[attr] = 1;
  Value v;
  bool found = false;
  for (const auto& [name, value] : options_.sets) {
    if (name == a.name) {
      v = from_shape(value);
      found = true;
    }
  }
  if (!found) {
    if (const shape::Value* property = lot_property(a.name)) {
      v = from_shape(*property);
      found = true;
    }
  }
  if (a.value != kNoExpr && (!found || std::holds_alternative<std::string>(v))) {
    State* saved = cur_;
    const std::span<const Value> saved_frame = frame;
    cur_ = &start_state_;
    frame = {};
    const Value fallback = evaluate(program_, a.value, *this);
    cur_ = saved;
    frame = saved_frame;
    if (!found) {
      v = fallback;
    } else if (std::holds_alternative<double>(fallback)) {
      // OpenStreetMap tags and many registers give numbers as text ("12", "12 m", "40'"): an
      // attr declared with a number takes such a text as that number, a length in metres
      // (CityEngine converts object attributes to the rule attribute's type too). Other text
      // ("approx. 10") keeps the default with a warning: one odd tag must not stop a city.
      const std::string& text = std::get<std::string>(v);
      if (std::optional<Value> number = number_from_text(text)) {
        v = *number;
      } else if (const std::optional<double> length = base::parse_length(text)) {
        v = *length;
      } else {
        warning(program_.nodes[a.value].range, "lot property '" + a.name + "' = \"" + text +
                                                   "\" is not a number; the default " +
                                                   as_text(fallback) + " is used");
        v = fallback;
      }
    }
  }
  values_[attr] = v;
  status_[attr] = 2;
  return v;
}

std::uint32_t Engine::add_mesh(std::shared_ptr<const Mesh> mesh,
                               std::shared_ptr<const kernel::Polygon> outline, Vec3 size) {
  if (!mesh && !outline) return 0;
  Geometry g;
  g.kind = Geometry::Kind::kMesh;
  if (outline) {
    g.rect_like = shape::is_rectangle(*outline, size.x, size.y);
    g.tag = mesh && !mesh->empty() ? mesh->tag(0) : FaceTag{};
    g.area = kernel::area(*outline);
  } else if (mesh) {
    g.box_like = shape::is_box(*mesh, size, &g.tags);
  }
  g.mesh = std::move(mesh);
  g.outline = std::move(outline);
  return add_geometry(std::move(g));
}

Materialized Engine::materialize(const Geometry& g, Vec3 size) {
  switch (g.kind) {
    case Geometry::Kind::kNone:
      return {};
    case Geometry::Kind::kBox:
      return {shape::box_mesh(size, g.tags), nullptr};
    case Geometry::Kind::kRect: {
      auto outline = std::make_shared<kernel::Polygon>(shape::rectangle_outline(size.x, size.y));
      auto mesh = shape::flat_mesh(*outline, g.tag);
      return {std::move(mesh), std::move(outline)};
    }
    case Geometry::Kind::kMesh:
      return {g.mesh, g.outline};
  }
  return {};
}

kernel::Polygon Engine::oriented(std::size_t i) const {
  kernel::Polygon polygon = lot_.polygons[i];
  kernel::normalize(polygon);
  if (i >= lot_.first_edges.size()) return polygon;
  const auto& [a, b] = lot_.first_edges[i];
  const auto near = [](kernel::Vec2 p, kernel::Vec2 q) {
    return std::fabs(p.x - q.x) <= 1e-6 && std::fabs(p.y - q.y) <= 1e-6;
  };
  kernel::Ring& ring = polygon.outer;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const kernel::Vec2 p = ring[k];
    const kernel::Vec2 q = ring[(k + 1) % ring.size()];
    if ((near(p, a) && near(q, b)) || (near(p, b) && near(q, a))) {
      std::rotate(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(k), ring.end());
      break;
    }
  }
  return polygon;
}

void Engine::start() {
  for (std::size_t i = 0; i < lot_.polygons.size(); ++i) {
    shape::ShapeTree tree;
    const shape::RootResult root = tree.create_root(oriented(i));
    if (!root.ok()) {
      throw DeriveError{base::Diagnostic::error(
          "CGA606", "lot '" + lot_.id + "' polygon " + std::to_string(i) + ": " + root.error,
          base::Span::whole(program_.source->name()))};
    }
    const shape::Shape& s = tree[root.id];
    State st;
    st.scope = s.scope;
    st.seed = shape::child_seed(lot_seed_, static_cast<std::uint32_t>(i));
    st.geometry = add_mesh(s.mesh, s.outline, s.scope.size);
    if (track_lineage_) st.lineage = add_lineage(0, st.seed);
    st.lot_axes = program_.cityengine;
    if (i == 0) start_state_ = st;
    starts_.push_back(st);
  }
  context_.object = &start_state_.scope;  // CityEngine's object frame: the initial shape's scope
  // Attribute values are fixed per lot, before any rule runs (CityEngine's attr semantics),
  // with a generator of their own.
  rng_ = shape::Rng(shape::child_seed(lot_seed_, 0xfffffffeU));
  cur_ = &start_state_;
  for (std::uint32_t a = 0; a < program_.attrs.size(); ++a) {
    if (a == program_.color_attr) continue;
    const Value v = lot_value(a, program_.attrs[a].range);
    if (!std::holds_alternative<std::monostate>(v)) {
      out_.attributes[program_.attrs[a].name] = to_shape(v);
    }
  }
  for (const auto& [name, value] : lot_.properties) out_.attributes.emplace(name, value);
  for (State& st : starts_) {
    st.next_child = 0;
    count_shape(program_.start);
    push_or_terminal(st, program_.start, 0);
  }
  flush_batch();
}

void Engine::loop() {
  while (true) {
    std::size_t level = pending_.size();
    for (std::size_t l = 0; l < pending_.size(); ++l) {
      if (!pending_[l].empty()) {
        level = l;
        break;
      }
    }
    if (level == pending_.size()) return;
    // Processed where it lies (a copy was read back in pieces other than those it was written
    // in: a store-forwarding stall on every shape), removed after; until then occlusion() passes
    // it over as it would a removed one. Nothing adds to pending_ before flush_batch().
    const Work& w = pending_[level].back();
    --pending_count_;
    current_ = &w;
    process(w);
    current_ = nullptr;
    pending_[level].pop_back();
    flush_batch();
  }
}

void Engine::flush_batch() {
  // Children go on the stack in reverse so the first one is derived first (depth first, in
  // successor order: the terminal list follows the grammar's reading order).
  for (auto it = batch_.rbegin(); it != batch_.rend(); ++it) pending_[it->level].push_back(*it);
  pending_count_ += batch_.size();
  out_.peak_pending = std::max(out_.peak_pending, pending_count_);
  batch_.clear();
}

[[noreturn]] void Engine::limit_error(std::string code, std::string what) {
  base::Span span = base::Span::whole(program_.source->name());
  if (rule_ != nullptr) {
    span = program_.span(rule_->id_range);
    what += " in " + program_.describe(*rule_);
  }
  base::Diagnostic d = base::Diagnostic::error(std::move(code), std::move(what), span);
  d.notes.push_back("in lot '" + lot_.id + "'");
  throw DeriveError{std::move(d)};
}

void Engine::process(const Work& w) {
  State st;
  st.scope = w.scope;
  st.seed = w.seed;
  st.geometry = w.geometry;
  st.attrs = w.attrs;
  st.index = w.index;
  st.total = w.total;
  st.frame = w.frame;
  st.selector = w.selector;
  st.lineage = w.lineage;
  st.lot_axes = w.lot_axes;
  depth_ = w.depth;
  cur_ = &st;
  frame = frame_of(w.frame);
  rng_ = shape::Rng(w.seed);
  rule_ = nullptr;
  for (std::uint32_t r : program_.rules_at[w.symbol][w.level]) {
    const CRule& rule = program_.rules[r];
    rule_ = &rule;
    if (rule.condition != kNoExpr && !condition_holds(r, rule)) continue;
    apply(rule, st);
    return;
  }
  // No rule of this level applies: try the next level with rules for the symbol (§II: a
  // shape with no applicable rule is terminal).
  for (std::uint32_t l : program_.levels_of[w.symbol]) {
    if (l > w.level) {
      Work next = w;
      next.level = static_cast<std::uint16_t>(l);
      batch_.push_back(next);
      return;
    }
  }
  terminal(st, w.symbol);
}

bool Engine::condition_holds(std::uint32_t r, const CRule& rule) {
  const auto holds = [&] {
    return as_bool(evaluate(program_, rule.condition, *this), program_.nodes[rule.condition].range);
  };
  if (!rule.condition_per_lot) return holds();
  // Asked on every shape of the symbol (a facade's walls ask for its style): the lot's answer.
  std::int8_t& known = lot_conditions_[r];
  if (known < 0) known = holds() ? 1 : 0;
  return known == 1;
}

double Engine::probability(const CRule& rule, std::uint32_t p) {
  const Range range = program_.nodes[p].range;
  const double v = as_number(evaluate(program_, p, *this), range);
  if (!(v >= 0 && v <= 1)) {
    base::Diagnostic d = base::Diagnostic::error(
        "CGA605",
        "the probability of " + program_.describe(rule) + " evaluates to " + as_text(Value(v)) +
            ", not a number in [0, 1] (seed 004 §IV.B, constraint 1)",
        program_.span(range));
    d.notes.push_back("in lot '" + lot_.id + "'");
    throw DeriveError{std::move(d)};
  }
  return v;
}

const CAlternative& Engine::choose(const CRule& rule) {
  if (rule.alternatives.size() == 1) {
    const std::uint32_t p = rule.alternatives.front().probability;
    if (p != kNoExpr) probability(rule, p);  // checked even when there is nothing to choose
    return rule.alternatives.front();
  }
  // Probabilities from the shape's generator; alternatives without one share what is left.
  std::vector<double> weights(rule.alternatives.size(), -1.0);
  double given = 0;
  std::size_t missing = 0;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    const std::uint32_t p = rule.alternatives[i].probability;
    if (p == kNoExpr) {
      ++missing;
      continue;
    }
    weights[i] = probability(rule, p);
    given += weights[i];
  }
  const double share = missing > 0 ? std::max(0.0, 1.0 - given) / static_cast<double>(missing) : 0;
  for (double& w : weights) {
    if (w < 0) w = share;
  }
  const std::size_t k = rng_.choice(weights);
  return rule.alternatives[k < weights.size() ? k : 0];
}

void Engine::apply(const CRule& rule, State& st) {
  ++out_.rule_applications;
  const CAlternative& alt = choose(rule);
  rule_scope_ = st.scope;
  std::vector<State> stack;
  run_items(alt.items, 0, st, stack);
  if (!st.consumed) terminal(st, rule.predecessor);
}

void Engine::warn(const CItem& c, std::string message) {
  const std::string name = c.info != nullptr ? std::string(c.info->name) : "operation";
  // Registry errors name the shape operation ("roof: ..."); say the CGA name instead.
  if (c.info != nullptr && !c.info->registry_op.empty()) {
    const std::string prefix = std::string(c.info->registry_op) + ": ";
    if (message.compare(0, prefix.size(), prefix) == 0) message.erase(0, prefix.size());
  }
  ++warnings_[{c.range.begin, name + ": " + message}];
}

void Engine::flush_warnings() {
  for (const auto& [key, count] : warnings_) {
    base::Diagnostic d = base::Diagnostic::warning(
        "CGA604",
        key.second + (count > 1 ? " (" + std::to_string(count) + " times)" : std::string()),
        program_.span(Range{key.first, key.first + 1}));
    d.notes.push_back("in lot '" + lot_.id + "'");  // among thousands of lots, which one
    out_.diagnostics.push_back(std::move(d));
  }
}

void Engine::run_items(const std::vector<CItem>& items, std::size_t from, State& st,
                       std::vector<State>& stack) {
  for (std::size_t i = from; i < items.size(); ++i) {
    const CItem& c = items[i];
    switch (c.code) {
      case OpCode::kSymbol:
        count_shape(c.symbol);
        {
          const std::uint64_t seed = shape::child_seed(st.seed, st.next_child++);
          const std::uint32_t lineage = track_lineage_ ? add_lineage(st.lineage, seed) : st.lineage;
          const std::uint32_t arguments = c.args.empty() ? 0 : new_frame(c.args, st);
          const State child = State::successor(st, seed, lineage, arguments);
          if (c.terminal) {
            terminal(child, c.symbol);
          } else {
            push_or_terminal(child, c.symbol, depth_ + 1U);
          }
        }
        st.consumed = true;
        break;
      case OpCode::kCase:
      case OpCode::kChance:
        // The chosen branch goes on with the shape; a chain ends its sequence
        // (parser_cityengine.cc) but inside `[ ]`, where the `]` comes after it.
        run_items(choose_branch(c, st).items, 0, st, stack);
        break;
      case OpCode::kNoOp:
        break;
      case OpCode::kEmpty:
        st.consumed = true;
        break;
      case OpCode::kPush: {
        State inner = st;
        inner.seed = shape::child_seed(st.seed, st.next_child++);
        if (track_lineage_) inner.lineage = add_lineage(st.lineage, inner.seed);
        stack.push_back(st);
        inner.next_child = 0;
        inner.consumed = false;
        inner.modified = false;
        st = inner;
        break;
      }
      case OpCode::kPop:
        if (stack.empty()) break;  // the parser balances brackets
        if (!st.consumed && st.modified) terminal(st, rule_->predecessor);
        st = stack.back();
        stack.pop_back();
        break;
      case OpCode::kTranslate: {
        Vec3 d{number(c.args[0], st), number(c.args[1], st), number(c.args[2], st)};
        if (lot_axes(st)) d = {d.x, -d.z, d.y};  // CityEngine's (x, normal, −y)
        st.scope.origin = st.scope.to_world(d);
        touch(st);
        break;
      }
      case OpCode::kRotate:
        rotate(c, st);
        break;
      case OpCode::kColor:
        color(c, st);
        break;
      case OpCode::kSet:
        if (c.attr == program_.color_attr) {  // set(material.color, v): checked as color(v)
          color(c, st);
          break;
        }
        set_attr(st, c.attr, eval(c.args[0], st));
        break;
      case OpCode::kSetScope:
        set_scope_translation(c, st);
        break;
      case OpCode::kPrint:
        print(c, st);
        break;
      case OpCode::kReport:
        report(c, st);
        break;
      case OpCode::kLabel:
        if (track_lineage_) add_occluder(st, as_text(eval(c.args[0], st)));
        break;
      case OpCode::kInsertShape:
        insert_shape(c, st);
        break;
      case OpCode::kSplit:
      case OpCode::kRepeat:
        split(c, st);
        st.consumed = true;
        break;
      case OpCode::kComp:
        comp(c, st);
        st.consumed = true;
        break;
      case OpCode::kSetback:
        setback(c, st);
        st.consumed = true;
        break;
      default:
        // Registry operations (kRegistry): without a block they replace the current shape
        // (extrude, scale, center, i, roof, offset, ...), with one they feed it.
        if (c.has_block) {
          block_operation(c, st);
          st.consumed = true;
          break;
        }
        if (!replace(c, items, i, st, stack)) return;
        break;
    }
  }
}

std::uint32_t Engine::new_frame(const std::vector<std::uint32_t>& args, State& st) {
  std::vector<Value> values;
  values.reserve(args.size());
  for (std::uint32_t a : args) values.push_back(eval(a, st));
  // eval() may have pointed `frame` into frame_values_: the vector grows only after it is used.
  for (Value& v : values) frame_values_.push_back(std::move(v));
  frame_begin_.push_back(frame_values_.size());
  frame = frame_of(st.frame);
  return static_cast<std::uint32_t>(frame_begin_.size() - 2);
}

// `case c : ... else : ...` takes the first branch whose condition holds; `30% : ... else : ...`
// draws from the shape's generator (the same shape and seed always take the same branch).
const CBranch& Engine::choose_branch(const CItem& c, State& st) {
  if (c.code == OpCode::kCase) {
    for (const CBranch& b : c.branches) {
      if (b.condition == kNoExpr) return b;
      if (as_bool(eval(b.condition, st), program_.nodes[b.condition].range)) return b;
    }
    return c.branches.back();
  }
  double draw = rng_.unit() * 100.0;
  for (const CBranch& b : c.branches) {
    if (b.condition == kNoExpr) return b;
    const double percent = number(b.condition, st);
    if (draw < percent) return b;
    draw -= percent;
  }
  return c.branches.back();
}

void Engine::rotate(const CItem& c, State& st) {
  const Vec3 d{number(c.args[0], st), number(c.args[1], st), number(c.args[2], st)};
  if (!std::isfinite(d.x) || !std::isfinite(d.y) || !std::isfinite(d.z)) {
    warn(c, "angles must be finite");
    return;
  }
  // As shape::rotate: intrinsic rotations about x, then y, then z, about the scope origin (or
  // its centre: CityEngine's r(scopeCenter, ...)).
  const Vec3 pivot = c.about_center ? st.scope.size * 0.5 : Vec3{};
  // On a lot CityEngine's y is the normal (Insula's z) and its z is Insula's −y.
  const bool lot = lot_axes(st);
  if (d.x != 0) st.scope = shape::rotated(st.scope, Axis::kX, d.x, pivot);
  if (d.y != 0) st.scope = shape::rotated(st.scope, lot ? Axis::kZ : Axis::kY, d.y, pivot);
  if (d.z != 0)
    st.scope = shape::rotated(st.scope, lot ? Axis::kY : Axis::kZ, lot ? -d.z : d.z, pivot);
  touch(st);
}

namespace {

// Equal values, numbers bit for bit (-0 is not 0 to print(), NaN is itself); arrays as the
// same array.
bool identical(const Value& a, const Value& b) {
  if (a.index() != b.index()) return false;
  if (const double* x = std::get_if<double>(&a)) {
    return std::bit_cast<std::uint64_t>(*x) == std::bit_cast<std::uint64_t>(std::get<double>(b));
  }
  return a == b;
}

}  // namespace

void Engine::set_attr(State& st, std::uint32_t attr, Value value) {
  // Nodes never change once made, so an equal one on the same chain serves (a few kept per
  // chain and attribute: a facade alternates a handful of colours).
  constexpr std::size_t kKept = 8;
  std::vector<std::uint32_t>& made =
      attr_nodes_made_[(std::uint64_t{st.attrs} << 32) | std::uint64_t{attr}];
  for (std::uint32_t n : made) {
    if (identical(out_.attr_nodes[n].value, value)) {
      st.attrs = n;
      touch(st);
      return;
    }
  }
  out_.attr_nodes.push_back({st.attrs, attr, std::move(value)});
  st.attrs = static_cast<std::uint32_t>(out_.attr_nodes.size() - 1);
  if (made.size() < kKept) made.push_back(st.attrs);
  touch(st);
}

void Engine::color(const CItem& c, State& st) {
  const bool literal = c.args.size() == 1 && program_.nodes[c.args[0]].code == ECode::kConst;
  if (!literal) {
    if (std::optional<std::string> hex = color_hex(c, st)) {
      set_attr(st, program_.color_attr, std::move(*hex));
    }
    return;
  }
  // A colour written as a literal (most are) is checked and normalised once per lot, and on a
  // chain it met before takes the node it took then: one lookup for each of a façade's walls,
  // and none while the literal meets the chain it met last (a façade's walls share theirs).
  if (last_literal_.size() <= c.args[0]) last_literal_.resize(c.args[0] + 1);
  LastLiteral& last = last_literal_[c.args[0]];
  if (last.node != 0 && last.chain == st.attrs) {
    st.attrs = last.node;
    touch(st);
    return;
  }
  const std::uint64_t key = (std::uint64_t{st.attrs} << 32) | std::uint64_t{c.args[0]};
  if (const auto it = literal_nodes_.find(key); it != literal_nodes_.end()) {
    last = {st.attrs, it->second};
    st.attrs = it->second;
    touch(st);
    return;
  }
  auto known = literal_colors_.find(c.args[0]);
  if (known == literal_colors_.end()) {
    std::optional<std::string> hex = color_hex(c, st);
    if (!hex) return;
    known = literal_colors_.emplace(c.args[0], std::move(*hex)).first;
  }
  const std::uint32_t chain = st.attrs;
  set_attr(st, program_.color_attr, Value(known->second));
  literal_nodes_.emplace(key, st.attrs);
  last = {chain, st.attrs};
}

std::optional<std::string> Engine::color_hex(const CItem& c, State& st) {
  if (c.args.size() != 1) {
    const double a = c.args.size() == 4 ? number(c.args[3], st) : 1.0;
    return hex_color(number(c.args[0], st), number(c.args[1], st), number(c.args[2], st), a,
                     c.args.size() == 4);
  }
  const Value v = eval(c.args[0], st);
  std::string hex = long_hex(as_text(v));
  // A CSS colour name too: OpenStreetMap's building:colour is "white" as often as "#ffffff".
  if (!valid_hex_color(hex)) {
    if (const std::optional<std::uint32_t> named = base::css_colour(as_text(v))) {
      hex = hex_color(((*named >> 16) & 0xFF) / 255.0, ((*named >> 8) & 0xFF) / 255.0,
                      (*named & 0xFF) / 255.0, 1, false);
    }
  }
  if (!valid_hex_color(hex)) {
    const std::string message =
        "color() expects \"#rrggbb\", \"#rrggbbaa\", \"#rgb\" or a CSS "
        "colour name, got \"" +
        as_text(v) + "\"";
    // CityEngine warns and keeps the colour (Esri's greenspace rules pass "").
    if (!program_.cityengine) throw EvalError{program_.nodes[c.args[0]].range, message};
    warning(program_.nodes[c.args[0]].range, message + ": unchanged");
    return std::nullopt;
  }
  std::transform(hex.begin(), hex.end(), hex.begin(), [](char ch) {
    return static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  });
  return hex;
}

void Engine::print(const CItem& c, State& st) {
  std::string text;
  for (std::size_t k = 0; k < c.args.size(); ++k) {
    if (k > 0) text += ' ';
    text += as_text(eval(c.args[k], st));
  }
  print(c.range, text);
}

void Engine::print(Range range, const std::string& text) {
  const base::Span at = program_.span(range);  // an imported file's rule prints its own name
  std::string line = at.file + ":" + std::to_string(at.line) + ": print:";
  // Appended in two steps: GCC 12 reports a false -Wrestrict on `" " + std::string`.
  if (!text.empty()) line.append(" ").append(text);
  out_.prints.push_back(std::move(line));
}

void Engine::report(const CItem& c, State& st) {
  const std::string name = as_text(eval(c.args[0], st));
  const Value value = eval(c.args[1], st);
  if (!std::holds_alternative<double>(value) && !std::holds_alternative<bool>(value)) {
    // CityEngine reports texts too: each distinct text is counted under "name=text".
    ReportEntry& e = out_.reports[name + "=" + as_text(value)];
    e.sum += 1;
    ++e.count;
    return;
  }
  ReportEntry& e = out_.reports[name];
  e.sum += as_number(value, program_.nodes[c.args[1]].range);
  ++e.count;
}

}  // namespace insula::lang::cga::detail
