#include "io/svg_writer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <queue>

#include "io/atomic_file.h"
#include "io/obj_writer.h"
#include "kernel/planar.h"
#include "kernel/polygon.h"
#include "shape/part_mesh.h"

namespace insula::io {
namespace {

using kernel::Vec2;
using kernel::Vec3;
using Ring2 = std::vector<Vec2>;

constexpr int kDecimals = 3;                  // 1 mm
constexpr double kDefaultPictureSize = 1000;  // px, the longer side

struct Segment {
  Vec2 a;
  Vec2 b;
};

// A building seen from above: its ground pieces and their outer outline.
struct Footprint {
  std::vector<Ring2> pieces;
  std::vector<Segment> outline;
};

std::vector<Ring2> faces_from_above(const shape::Building& building, bool ground_only) {
  std::vector<Ring2> rings;
  for (const shape::Part& part : building.parts) {
    for (std::size_t f = 0; f < part.mesh.face_count(); ++f) {
      const bool ground = part.mesh.tag(f).semantic == kernel::SemanticClass::kGroundSurface;
      if (ground_only ? !ground : kernel::face_normal(part.mesh, f).z > -0.5) continue;
      Ring2 ring;
      for (std::uint32_t v : part.mesh.face(f)) ring.push_back(kernel::drop(part.mesh.position(v)));
      rings.push_back(std::move(ring));
    }
  }
  return rings;
}

using EdgeKey = std::array<std::int64_t, 4>;

EdgeKey edge_key(Vec2 a, Vec2 b) {
  const auto q = [](double v) { return std::llround(v * 1e6); };  // 1 µm grid
  return {q(a.x), q(a.y), q(b.x), q(b.y)};
}

// Edges of the pieces that no other piece shares (in the opposite direction): the outline.
std::vector<Segment> outline_of(const std::vector<Ring2>& pieces) {
  std::map<EdgeKey, int> directed;
  for (const Ring2& ring : pieces) {
    for (std::size_t i = 0; i < ring.size(); ++i)
      ++directed[edge_key(ring[i], ring[(i + 1) % ring.size()])];
  }
  std::vector<Segment> outline;
  for (const Ring2& ring : pieces) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 a = ring[i];
      const Vec2 b = ring[(i + 1) % ring.size()];
      if (!directed.contains(edge_key(b, a))) outline.push_back({a, b});
    }
  }
  return outline;
}

Footprint footprint_of(const shape::Building& building) {
  Footprint footprint;
  footprint.pieces = faces_from_above(building, true);
  if (footprint.pieces.empty()) footprint.pieces = faces_from_above(building, false);
  footprint.outline = outline_of(footprint.pieces);
  return footprint;
}

// Even-odd crossing test of one ring.
bool inside_ring(const Ring2& ring, Vec2 p) {
  bool in = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Vec2 a = ring[i];
    const Vec2 b = ring[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

double distance_to(Segment s, Vec2 p) {
  return kernel::distance_to_segment(p, s.a, s.b);
}

// Distance to the outline, negative outside every piece.
double signed_distance(const Footprint& footprint, Vec2 p) {
  double d = 1e300;
  for (const Segment& s : footprint.outline) d = std::min(d, distance_to(s, p));
  const bool in = std::any_of(footprint.pieces.begin(), footprint.pieces.end(),
                              [&](const Ring2& ring) { return inside_ring(ring, p); });
  return in ? d : -d;
}

struct Cell {
  Vec2 centre;
  double half = 0;
  double distance = 0;
  double potential = 0;  // the best distance any point of the cell can reach
  bool operator<(const Cell& other) const { return potential < other.potential; }
};

Cell make_cell(const Footprint& footprint, Vec2 centre, double half) {
  const double d = signed_distance(footprint, centre);
  return {centre, half, d, d + half * std::sqrt(2.0)};
}

kernel::Bounds2 bounds_of(const std::vector<Ring2>& rings) {
  kernel::Bounds2 b;
  for (const Ring2& ring : rings) kernel::add(b, ring);
  return b;
}

constexpr int kMaxSeedCells = 64;          // seed cells along the long side of the bounding box
constexpr int kMaxCellsProcessed = 20000;  // refinement budget (cells popped from the queue)

// Pole of inaccessibility by best-first quadtree search (the "polylabel" idea, Garcia-Castellanos
// & Lombardo 2007 grid search refined as a priority queue): cells are split while they could still
// hold a point farther from the outline than the best found, within 1/200 of the footprint size.
// Seed cells are squares of the short side, but never smaller than the long side / 64: a sliver
// (1000 m x 10 µm) would otherwise seed (long / short)^2 cells. At most ~64 x 64 seed cells and
// kMaxCellsProcessed refinement steps, so the cost is bounded for any shape; a bounding box with a
// zero or non-finite side (or no outline) gives the bounding-box centre.
Vec2 visual_centre(const Footprint& footprint) {
  const kernel::Bounds2 b = bounds_of(footprint.pieces);
  const Vec2 size = b.max - b.min;
  const Vec2 middle = (b.min + b.max) / 2;
  const double long_side = std::max(size.x, size.y);
  const double short_side = std::min(size.x, size.y);
  if (footprint.outline.empty() || !std::isfinite(long_side) || !(short_side > 0)) return middle;
  const double cell = std::max(short_side, long_side / kMaxSeedCells);
  const double precision = long_side / 200;
  std::priority_queue<Cell> queue;
  // Cells along one side (ceil, tolerant of rounding), at most kMaxSeedCells + 1.
  const auto count = [&](double side) {
    const double n = std::clamp(std::ceil(side / cell - 1e-9), 1.0, kMaxSeedCells + 1.0);
    return static_cast<int>(n);
  };
  const int nx = count(size.x);
  const int ny = count(size.y);
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      const Vec2 centre{b.min.x + (i + 0.5) * cell, b.min.y + (j + 0.5) * cell};
      queue.push(make_cell(footprint, centre, cell / 2));
    }
  }
  Cell best = make_cell(footprint, middle, 0);
  for (int step = 0; !queue.empty() && step < kMaxCellsProcessed; ++step) {
    const Cell c = queue.top();
    queue.pop();
    if (c.distance > best.distance) best = c;
    if (c.potential - best.distance <= precision) continue;
    const double h = c.half / 2;
    for (const Vec2 offset : {Vec2{-h, -h}, Vec2{h, -h}, Vec2{-h, h}, Vec2{h, h}}) {
      queue.push(make_cell(footprint, c.centre + offset, h));
    }
  }
  return best.centre;
}

// Cut segments of a planar face with the plane z = height (vertices on the plane count as above).
void section_face(const kernel::Mesh& mesh, std::size_t face, double height,
                  std::vector<Segment>& out) {
  const Vec3 direction = kernel::cross(kernel::face_normal(mesh, face), Vec3{0, 0, 1});
  if (kernel::length(direction) < 1e-9) return;
  const auto loop = mesh.face(face);
  std::vector<Vec3> points;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec3 a = mesh.position(loop[i]);
    const Vec3 b = mesh.position(loop[(i + 1) % loop.size()]);
    if ((a.z >= height) == (b.z >= height)) continue;
    points.push_back(a + (b - a) * ((height - a.z) / (b.z - a.z)));
  }
  std::sort(points.begin(), points.end(),
            [&](Vec3 p, Vec3 q) { return kernel::dot(p, direction) < kernel::dot(q, direction); });
  for (std::size_t i = 0; i + 1 < points.size(); i += 2) {
    out.push_back({kernel::drop(points[i]), kernel::drop(points[i + 1])});
  }
}

// Maps local meters to picture coordinates: south-west corner of the content at (0, 0), y down.
struct Frame {
  kernel::Bounds2 content;
  double margin = 1;
  double pixels_per_meter = 1;
  Vec2 map(Vec2 p) const { return {p.x - content.min.x, content.max.y - p.y}; }
  double width() const { return content.max.x - content.min.x; }
  double height() const { return content.max.y - content.min.y; }
  double view_width() const { return width() + 2 * margin; }
  double view_height() const { return height() + 3 * margin; }  // one more below: scale bar
  // A line width given in pixels of the picture, in meters (not every renderer knows
  // vector-effect="non-scaling-stroke", so widths are real lengths).
  double pixels(double px) const { return px / pixels_per_meter; }
};

std::string number(double v) {
  return format_decimal(v, kDecimals);
}

std::string point(Vec2 p) {
  return number(p.x) + " " + number(p.y);
}

// Path data is built with append: GCC 12 reports a false -Wrestrict on `"M" + std::string`.
void move_or_line(std::string& d, char command, Vec2 p) {
  if (!d.empty()) d += ' ';
  d += command;
  d += point(p);
}

std::string path_of_rings(const std::vector<Ring2>& rings, const Frame& frame) {
  std::string d;
  for (const Ring2& ring : rings) {
    for (std::size_t i = 0; i < ring.size(); ++i)
      move_or_line(d, i == 0 ? 'M' : 'L', frame.map(ring[i]));
    d += " Z";
  }
  return d;
}

// Segments as path data; a segment starting where the previous one ended continues the same
// subpath (so corners get line joins), and a subpath back at its start is closed with Z.
std::string path_of_segments(const std::vector<Segment>& segments, const Frame& frame) {
  std::string d;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Segment& s = segments[i];
    if (i == 0 || !(segments[i - 1].b == s.a)) {
      if (i > 0) d += ' ';
      d += 'M';
      d += point(frame.map(s.a));
    }
    const bool closes = i + 1 < segments.size() ? !(segments[i + 1].a == s.b) : true;
    std::size_t start = i;
    while (start > 0 && segments[start - 1].b == segments[start].a) --start;
    if (closes && start != i && segments[start].a == s.b) {
      d += " Z";
    } else {
      move_or_line(d, 'L', frame.map(s.b));
    }
  }
  return d;
}

// The largest 1, 2 or 5 times a power of ten not above `limit` (meters).
double nice_length(double limit) {
  const double power = std::pow(10.0, std::floor(std::log10(limit)));
  for (double m : {5.0, 2.0, 1.0}) {
    if (m * power <= limit) return m * power;
  }
  return power;
}

struct Drawing {
  std::vector<std::string> ids;
  std::vector<Footprint> footprints;
  std::vector<Segment> section;
};

Drawing collect(const shape::Scene& scene, const SvgOptions& options) {
  Drawing drawing;
  for (std::size_t b = 0; b < scene.buildings.size(); ++b) {
    const shape::Building& building = scene.buildings[b];
    drawing.ids.push_back(building.id.empty() ? "building" + std::to_string(b) : building.id);
    drawing.footprints.push_back(footprint_of(building));
    if (!options.section_height) continue;
    for (const shape::Part& part : building.parts) {
      for (std::size_t f = 0; f < part.mesh.face_count(); ++f) {
        section_face(part.mesh, f, *options.section_height, drawing.section);
      }
    }
  }
  return drawing;
}

Frame frame_of(const Drawing& drawing, const SvgOptions& options) {
  Frame frame;
  for (const Footprint& footprint : drawing.footprints) {
    for (const Ring2& ring : footprint.pieces) {
      for (Vec2 p : ring) frame.content.add(p);
    }
  }
  for (const Segment& s : drawing.section) {
    frame.content.add(s.a);
    frame.content.add(s.b);
  }
  if (frame.content.empty()) frame.content = {{0, 0}, {1, 1}};
  frame.margin = std::max(1.0, 0.1 * std::max(frame.width(), frame.height()));
  frame.pixels_per_meter =
      options.pixels_per_meter > 0
          ? options.pixels_per_meter
          : kDefaultPictureSize / std::max(frame.view_width(), frame.view_height());
  return frame;
}

std::string header(const shape::Scene& scene, const Frame& frame) {
  const double m = frame.margin;
  const double view_width = frame.view_width();
  const double view_height = frame.view_height();
  const double ppm = frame.pixels_per_meter;
  const Vec3 corner =
      scene.origin + kernel::lift(Vec2{frame.content.min.x, frame.content.max.y}, 0);
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(view_width * ppm) +
         "\" height=\"" + number(view_height * ppm) + "\" viewBox=\"" + number(-m) + " " +
         number(-m) + " " + number(view_width) + " " + number(view_height) + "\">\n";
  out += "<title>Insula plan</title>\n";
  out += "<desc>Units: meters, north up. Picture (0, 0) is world (" + format_decimal(corner.x, 6) +
         ", " + format_decimal(corner.y, 6) + ")" +
         (scene.crs.empty() ? "" : " in " + xml_escape(scene.crs)) +
         "; picture y grows southwards.</desc>\n";
  out += "<rect x=\"" + number(-m) + "\" y=\"" + number(-m) + "\" width=\"" + number(view_width) +
         "\" height=\"" + number(view_height) + "\" fill=\"#ffffff\"/>\n";
  return out;
}

std::string footprints_svg(const Drawing& drawing, const Frame& frame, bool section) {
  std::string out = "<g id=\"footprints\" stroke-linejoin=\"round\">\n";
  const char* fill = section ? "#eeeeee" : "#e8dcc4";
  for (std::size_t b = 0; b < drawing.footprints.size(); ++b) {
    const Footprint& footprint = drawing.footprints[b];
    if (footprint.pieces.empty()) continue;
    out += "<g class=\"building\" data-id=\"" + xml_escape(drawing.ids[b]) + "\">\n";
    out += "<path d=\"" + path_of_rings(footprint.pieces, frame) + "\" fill=\"" + fill +
           "\" stroke=\"none\"/>\n";
    out += "<path d=\"" + path_of_segments(footprint.outline, frame) +
           "\" fill=\"none\" stroke=\"#333333\" stroke-width=\"" +
           format_decimal(frame.pixels(1.5), 6) + "\"/>\n";
    out += "</g>\n";
  }
  out += "</g>\n";
  if (section && !drawing.section.empty()) {
    out += "<g id=\"section\">\n<path d=\"" + path_of_segments(drawing.section, frame) +
           "\" fill=\"none\" stroke=\"#000000\" stroke-width=\"" +
           format_decimal(frame.pixels(3), 6) + "\" stroke-linecap=\"round\"/>\n</g>\n";
  }
  return out;
}

std::string labels_svg(const Drawing& drawing, const Frame& frame) {
  const double size = std::max(0.3, 0.03 * std::max(frame.width(), frame.height()));
  std::string out = "<g id=\"labels\" font-family=\"sans-serif\" font-size=\"" + number(size) +
                    "\" text-anchor=\"middle\" fill=\"#000000\">\n";
  for (std::size_t b = 0; b < drawing.footprints.size(); ++b) {
    if (drawing.footprints[b].pieces.empty()) continue;
    const Vec2 at = frame.map(visual_centre(drawing.footprints[b]));
    out += "<text x=\"" + number(at.x) + "\" y=\"" + number(at.y) +
           "\" dominant-baseline=\"central\">" + xml_escape(drawing.ids[b]) + "</text>\n";
  }
  return out + "</g>\n";
}

std::string scale_bar_svg(const Frame& frame) {
  const double m = frame.margin;
  const double length = nice_length(std::max(frame.width(), 2 * m) / 4);
  const double y = frame.height() + m;
  const double tick = m / 5;
  std::string out = "<g id=\"scale-bar\" stroke=\"#000000\" fill=\"none\">\n";
  out += "<path d=\"M0 " + number(y - tick) + " L0 " + number(y) + " L" + number(length) + " " +
         number(y) + " L" + number(length) + " " + number(y - tick) + "\" stroke-width=\"" +
         format_decimal(frame.pixels(1.5), 6) + "\"/>\n";
  out +=
      "<text x=\"" + number(length / 2) + "\" y=\"" + number(y + 2 * tick) +
      "\" font-family=\"sans-serif\" font-size=\"" + number(1.5 * tick) +
      "\" text-anchor=\"middle\" dominant-baseline=\"central\" fill=\"#000000\" stroke=\"none\">" +
      format_decimal(length, 3) + " m</text>\n";
  return out + "</g>\n";
}

std::string north_arrow_svg(const Frame& frame) {
  const double m = frame.margin;
  const double x = frame.width() + m / 2;
  const double top = m / 10;
  const double h = m / 2;
  std::string out = "<g id=\"north-arrow\">\n";
  out += "<path d=\"M" + number(x) + " " + number(top) + " L" + number(x + h / 3) + " " +
         number(top + h) + " L" + number(x) + " " + number(top + 0.75 * h) + " L" +
         number(x - h / 3) + " " + number(top + h) + " Z\" fill=\"#000000\"/>\n";
  out += "<text x=\"" + number(x) + "\" y=\"" + number(top + h + h / 3) +
         "\" font-family=\"sans-serif\" font-size=\"" + number(h / 2) +
         "\" text-anchor=\"middle\" dominant-baseline=\"central\">N</text>\n";
  return out + "</g>\n";
}

// ---- Floor plans (shape::Building::plans; seed 000 "look at its plan") ----------------------
// One panel per storey level, side by side from level 0 at the left, all panels at the same
// scale and over the same extent, each titled "storey <level>". A panel draws the rooms of every
// building's plan of that level (filled by room type, labelled with name and area), the walls
// (exterior darker), windows (a thin double line across the wall), doors (the leaf from its hinge
// and its swing arc; entrances in red) and stairs (treads and an arrow up).

// A pale fill per room type, stable across runs (FNV-1a of the type picks a hue).
std::string room_fill(std::string_view type) {
  std::uint32_t h = 2166136261U;
  for (char c : type) h = (h ^ static_cast<unsigned char>(c)) * 16777619U;
  static constexpr std::array<const char*, 10> kFills = {"#f6e3c8", "#dcebd4", "#d6e4f0", "#f2d9de",
                                                         "#e9e1f2", "#f5f0c8", "#d9efec", "#eedfd0",
                                                         "#e0e0e0", "#f0e4ea"};
  return kFills[h % kFills.size()];
}

std::vector<Ring2> rings_of(const kernel::Polygon& polygon) {
  std::vector<Ring2> rings;
  rings.push_back(polygon.outer);
  for (const kernel::Ring& hole : polygon.holes) rings.push_back(hole);
  return rings;
}

kernel::Bounds2 plan_bounds(const shape::Scene& scene) {
  kernel::Bounds2 b;
  for (const shape::Building& building : scene.buildings) {
    for (const shape::StoreyPlan& plan : building.plans) {
      for (const shape::PlanWall& wall : plan.walls) {
        for (Vec2 p : wall.outline.outer) b.add(p);
      }
      for (const shape::PlanRoom& room : plan.rooms) {
        for (Vec2 p : room.outline.outer) b.add(p);
      }
    }
  }
  return b;
}

int plan_levels(const shape::Scene& scene, int& lowest) {
  int lo = 0;
  int hi = -1;
  bool any = false;
  for (const shape::Building& building : scene.buildings) {
    for (const shape::StoreyPlan& plan : building.plans) {
      lo = any ? std::min(lo, plan.level) : plan.level;
      hi = any ? std::max(hi, plan.level) : plan.level;
      any = true;
    }
  }
  lowest = lo;
  return any ? hi - lo + 1 : 0;
}

std::string fill_path(const std::vector<Ring2>& rings, const Frame& frame, const std::string& fill,
                      Vec2 shift) {
  std::vector<Ring2> moved = rings;
  for (Ring2& ring : moved) {
    for (Vec2& p : ring) p = p + shift;
  }
  return "<path d=\"" + path_of_rings(moved, frame) + "\" fill=\"" + fill +
         "\" fill-rule=\"evenodd\"/>\n";
}

std::string line(Vec2 a, Vec2 b, const Frame& frame) {
  return "<path d=\"M" + point(frame.map(a)) + " L" + point(frame.map(b)) + "\"/>\n";
}

// A room's floor, filled by its type, naming the room (`data-room`, and a `<title>` that viewers
// show on hover) so a page can tell which room was clicked.
std::string room_path(const shape::PlanRoom& room, const Frame& frame, Vec2 shift) {
  std::string path = fill_path(rings_of(room.outline), frame, room_fill(room.type), shift);
  const std::string name = xml_escape(room.name);
  path.replace(path.size() - 3, 3,
               " data-room=\"" + name + "\" data-type=\"" + xml_escape(room.type) + "\"><title>" +
                   name + ", " + format_decimal(room.area, 1) + " m²</title></path>\n");
  return path;
}

std::string room_label(const shape::PlanRoom& room, const Frame& frame, Vec2 shift, double size) {
  Footprint footprint;
  footprint.pieces = rings_of(room.outline);
  footprint.outline = outline_of(footprint.pieces);
  const Vec2 at = frame.map(visual_centre(footprint) + shift);
  return "<text x=\"" + number(at.x) + "\" y=\"" + number(at.y - 0.6 * size) + "\">" +
         xml_escape(room.name) + "</text>\n<text x=\"" + number(at.x) + "\" y=\"" +
         number(at.y + 0.6 * size) + "\">" + format_decimal(room.area, 1) + " m²</text>\n";
}

std::string opening_svg(const shape::PlanOpening& o, const Frame& frame, Vec2 shift) {
  const Vec2 a = o.a + shift;
  const Vec2 b = o.b + shift;
  const double width = kernel::length(b - a);
  if (!(width > 0)) return {};
  if (o.kind == shape::PlanOpeningKind::kWindow) {
    // A light pane across the wall between two lines (the plan has no wall thickness here: the
    // lines stand 0.08 m either side of the wall's middle).
    const Vec2 n = Vec2{-(b - a).y, (b - a).x} / width * 0.08;
    const Ring2 pane{a + n, b + n, b - n, a - n};
    return "<g class=\"window\" stroke=\"#1f5fa8\">\n<path d=\"" + path_of_rings({pane}, frame) +
           "\" fill=\"#dcebf7\" stroke=\"none\"/>\n" + line(a + n, b + n, frame) +
           line(a - n, b - n, frame) + "</g>\n";
  }
  // The leaf stands open at right angles from the hinge `a`; the arc sweeps from its tip to `b`.
  const Vec2 tip = a + o.swing * width;
  const Vec2 p = frame.map(tip);
  const Vec2 q = frame.map(b);
  // Picture y is flipped, so a counter-clockwise turn in the plan is clockwise in the picture.
  const double turn = (b - a).x * o.swing.y - (b - a).y * o.swing.x;
  const char* sweep = turn > 0 ? "1" : "0";
  const char* colour = o.kind == shape::PlanOpeningKind::kEntrance ? "#b22222" : "#333333";
  return std::string("<g class=\"") +
         (o.kind == shape::PlanOpeningKind::kEntrance ? "entrance" : "door") + "\" stroke=\"" +
         colour + "\">\n" + line(a, tip, frame) + "<path d=\"M" + point(p) + " A" + number(width) +
         " " + number(width) + " 0 0 " + sweep + " " + point(q) + "\" stroke-dasharray=\"" +
         number(width / 12) + "\"/>\n</g>\n";
}

std::string stair_svg(const shape::PlanStair& stair, const Frame& frame, Vec2 shift) {
  std::string out = "<g class=\"stair\" stroke=\"#333333\">\n";
  std::vector<Ring2> rings = rings_of(stair.outline);
  for (Ring2& ring : rings) {
    for (Vec2& p : ring) p = p + shift;
  }
  out += "<path d=\"" + path_of_rings(rings, frame) + "\" fill=\"#ffffff\"/>\n";
  const Vec2 from = stair.up_from + shift;
  const Vec2 to = stair.up_to + shift;
  const double run = kernel::length(to - from);
  if (run > 0) {
    const Vec2 dir = (to - from) / run;
    const Vec2 side{-dir.y, dir.x};
    // Half the flight's width from the arrow: the extent of the outline across the arrow.
    double half = 0;
    for (Vec2 p : stair.outline.outer)
      half = std::max(half, std::abs(kernel::dot(p + shift - from, side)));
    const int treads = std::max(2, static_cast<int>(std::round(run / 0.3)));
    for (int i = 1; i < treads; ++i) {
      const Vec2 c = from + dir * (run * i / treads);
      out += line(c - side * half, c + side * half, frame);
    }
    out += line(from, to, frame);
    out += line(to, to - dir * 0.35 + side * 0.2, frame) +
           line(to, to - dir * 0.35 - side * 0.2, frame);
  }
  return out + "</g>\n";
}

std::string storey_panel(const shape::Scene& scene, int level, const Frame& frame, Vec2 shift,
                         double text_size) {
  std::string rooms;
  std::string walls;
  std::string labels;
  std::string openings;
  std::string stairs;
  for (const shape::Building& building : scene.buildings) {
    for (const shape::StoreyPlan& plan : building.plans) {
      if (plan.level != level) continue;
      for (const shape::PlanRoom& room : plan.rooms) {
        rooms += room_path(room, frame, shift);
        labels += room_label(room, frame, shift, text_size);
      }
      for (const shape::PlanWall& wall : plan.walls) {
        walls +=
            fill_path(rings_of(wall.outline), frame, wall.exterior ? "#2b2b2b" : "#6b6b6b", shift);
      }
      for (const shape::PlanOpening& o : plan.openings) openings += opening_svg(o, frame, shift);
      for (const shape::PlanStair& s : plan.stairs) stairs += stair_svg(s, frame, shift);
    }
  }
  const double line_width = frame.pixels(1.2);
  std::string out = "<g class=\"storey\" data-level=\"" + std::to_string(level) + "\">\n";
  const Vec2 title = frame.map(Vec2{frame.content.min.x, frame.content.max.y} + shift);
  out += "<text x=\"" + number(title.x) + "\" y=\"" + number(title.y - 0.5 * frame.margin) +
         "\" font-family=\"sans-serif\" font-size=\"" + number(1.6 * text_size) +
         "\" fill=\"#000000\">storey " + std::to_string(level) + "</text>\n";
  out += "<g class=\"rooms\" stroke=\"none\">\n" + rooms + "</g>\n";
  out += "<g class=\"stairs\" fill=\"none\" stroke-width=\"" + format_decimal(line_width, 6) +
         "\">\n" + stairs + "</g>\n";
  out += "<g class=\"walls\" stroke=\"none\">\n" + walls + "</g>\n";
  out += "<g class=\"openings\" fill=\"none\" stroke-width=\"" + format_decimal(line_width, 6) +
         "\">\n" + openings + "</g>\n";
  out += "<g class=\"room-labels\" font-family=\"sans-serif\" font-size=\"" + number(text_size) +
         "\" text-anchor=\"middle\" dominant-baseline=\"central\" fill=\"#000000\">\n" + labels +
         "</g>\n";
  return out + "</g>\n";
}

std::string plans_svg(const shape::Scene& scene, const SvgOptions& options) {
  int lowest = 0;
  const int levels = plan_levels(scene, lowest);
  const kernel::Bounds2 extent = plan_bounds(scene);
  const double width = extent.max.x - extent.min.x;
  const double height = extent.max.y - extent.min.y;
  const double gap = std::max(1.0, 0.1 * std::max(width, height));
  // The frame's content spans every panel; panel k is shifted by k * (width + gap) to the east.
  Frame frame;
  frame.content = extent;
  frame.content.max.x += (levels - 1) * (width + gap);
  frame.margin = gap;
  frame.pixels_per_meter = options.pixels_per_meter > 0
                               ? options.pixels_per_meter
                               : 1600 / std::max(frame.view_width(), frame.view_height());
  // Labels about 0.35 m tall, smaller when the plan is large, never below 2 px.
  const double text_size =
      std::max(frame.pixels(2 * 7), std::min(0.35, 0.025 * std::max(width, height)));
  std::string out = header(scene, frame);
  for (int k = 0; k < levels; ++k) {
    out += storey_panel(scene, lowest + k, frame, Vec2{k * (width + gap), 0}, text_size);
  }
  out += scale_bar_svg(frame);
  out += north_arrow_svg(frame);
  return out + "</svg>\n";
}

bool has_plans(const shape::Scene& scene) {
  return std::any_of(scene.buildings.begin(), scene.buildings.end(), [](const shape::Building& b) {
    return std::any_of(b.plans.begin(), b.plans.end(), [](const shape::StoreyPlan& p) {
      return !p.rooms.empty() || !p.walls.empty();
    });
  });
}

// Length of the UTF-8 sequence starting at text[i], or 0 when it is not valid UTF-8.
std::size_t utf8_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  const std::size_t n = lead < 0x80           ? 1
                        : (lead >> 5) == 0x6  ? 2
                        : (lead >> 4) == 0xE  ? 3
                        : (lead >> 3) == 0x1E ? 4
                                              : 0;
  if (n == 0 || i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
  }
  return n;
}

}  // namespace

std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    const std::size_t n = utf8_length(text, i);
    if (n > 1) {
      out.append(text.substr(i, n));
      i += n;
      continue;
    }
    ++i;
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        const bool control = static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n';
        out += (n == 0 || control || c == '\x7f') ? '?' : c;
    }
  }
  return out;
}

std::string svg_text(const shape::Scene& input, const SvgOptions& options) {
  // Plans see placed furniture too: instance parts become plain parts (shape/part_mesh.h).
  shape::Scene expanded;
  const shape::Scene& scene = shape::expand_instances(input, expanded);
  if (!options.section_height && has_plans(scene)) return plans_svg(scene, options);
  const Drawing drawing = collect(scene, options);
  const Frame frame = frame_of(drawing, options);
  std::string out = header(scene, frame);
  out += footprints_svg(drawing, frame, options.section_height.has_value());
  if (options.labels) out += labels_svg(drawing, frame);
  out += scale_bar_svg(frame);
  out += north_arrow_svg(frame);
  return out + "</svg>\n";
}

std::string write_svg(const shape::Scene& scene, const std::filesystem::path& path,
                      const SvgOptions& options) {
  return write_file_atomically(path, svg_text(scene, options));
}

}  // namespace insula::io
