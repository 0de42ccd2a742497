#include "io/render_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <span>
#include <unordered_map>
#include <vector>

#include "kernel/mesh.h"
#include "kernel/planar.h"
#include "kernel/polygon.h"
#include "kernel/triangulate.h"

namespace insula::io::raster {
namespace {

using kernel::Mesh;
using kernel::Vec2;
using kernel::Vec3;

constexpr double kDegree = std::numbers::pi / 180.0;
// Lighting (docs/renderer.md, "Shading"): a sun fixed relative to the camera, so every view shows
// its roofs and walls in the same readable way, plus a sky term and a weak fill light.
constexpr double kSunAzimuthOffset = -30.0;  // degrees from the camera azimuth
constexpr double kSunElevation = 50.0;       // degrees
constexpr double kFillAzimuthOffset = 120.0;
constexpr double kFillElevation = 10.0;
constexpr float kAmbient = 0.30F;
constexpr float kDiffuse = 0.72F;
constexpr float kFill = 0.16F;
// Buildings smaller than this on screen (output pixels) get no lines: at district scale their
// outlines would merge into a dark mat, and shading alone reads better.
constexpr double kMinOutlinedSize = 24.0;
constexpr double kWeldQuantum = 1e-6;  // meters; vertices closer than this share outline edges

Vec3 direction(double azimuth_deg, double elevation_deg) {
  const double a = azimuth_deg * kDegree;
  const double e = elevation_deg * kDegree;
  return {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

bool finite(Vec3 p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// A face is drawn when it has 3 or more vertices, all finite.
bool drawable(const Mesh& mesh, std::size_t face) {
  const auto loop = mesh.face(face);
  if (loop.size() < 3) return false;
  for (std::uint32_t v : loop) {
    if (!finite(mesh.position(v))) return false;
  }
  return true;
}

// Everything the face loop needs that does not change between parts.
struct Context {
  const shape::Scene& scene;
  const RenderOptions& options;
  const Camera& camera;
  Framebuffer& framebuffer;
  Vec3 sun;
  Vec3 fill;
  double ground = 0;  // Z of the shadow-receiving ground plane
  double cos_crease = 1;
  bool lines = true;           // whether the current building is large enough on screen for lines
  std::uint32_t building = 0;  // 1-based index of the current building, its shades' owner
  std::vector<Stroke> strokes;
  const shape::UvMap* uv = nullptr;  // the current part's texture coordinates, if any
  // Shades of textured pixels by (owner, quantised colour): a texture adds as many as it shows.
  std::unordered_map<std::uint64_t, std::uint32_t> texel_shades{};
};

// A face's colour in the view: its material's, times the mean colour of the material's image
// when it has one (the view draws no textures; a sign still shows as its dominant colour).
std::array<float, 4> view_colour(const Context& context, const kernel::FaceTag& tag) {
  const shape::Material material = context.scene.material_for(tag);
  std::array<float, 4> rgba = material.rgba;
  const shape::Image* image = material.image.get();
  if (image != nullptr && !image->rgba.empty()) {
    std::array<double, 3> sum{};
    const std::size_t pixels = image->rgba.size() / 4;
    for (std::size_t p = 0; p < pixels; ++p) {
      for (std::size_t c = 0; c < 3; ++c) sum[c] += image->rgba[p * 4 + c];
    }
    for (std::size_t c = 0; c < 3; ++c) {
      rgba[c] *= static_cast<float>(sum[c] / (255.0 * static_cast<double>(pixels)));
    }
  }
  return rgba;
}

float light_of(const Context& context, Vec3 normal) {
  const float sky = kAmbient * static_cast<float>(0.8 + 0.2 * normal.z);
  const float sun = kDiffuse * static_cast<float>(std::max(0.0, dot(normal, context.sun)));
  const float fill = kFill * static_cast<float>(std::max(0.0, dot(normal, context.fill)));
  return sky + sun + fill;
}

Rgb shade(const Context& context, const kernel::FaceTag& tag, Vec3 normal) {
  const std::array<float, 4> colour = view_colour(context, tag);
  const float light = light_of(context, normal);
  return {colour[0] * light, colour[1] * light, colour[2] * light};
}

// sRGB texel values to linear (IEC 61966-2-1).
const std::array<float, 256>& linear_table() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (std::size_t i = 0; i < t.size(); ++i) {
      const double c = static_cast<double>(i) / 255.0;
      t[i] = static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
    }
    return t;
  }();
  return table;
}

// A textured face as the view shows it: per pixel, the point of the face's plane under the pixel
// centre, its texture coordinates, the nearest texel (repeating) times the material's colour and
// the face's light. Colours are quantised to 12 bits per channel to share shades.
struct TexturedFace {
  const Context& context;
  const shape::Image& image;
  std::array<float, 4> tint;
  float light = 1;
  Vec3 normal;
  double plane = 0;  // dot(normal, p) of the face's points

  Rgb colour_at(float sx, float sy) const {
    const Camera& c = context.camera;
    const double a = (sx - c.half_width) / c.scale + c.u0;
    const double b = c.v0 - (sy - c.half_height) / c.scale;
    const double facing = dot(normal, c.forward);
    const double t = std::abs(facing) > 1e-9
                         ? (plane - a * dot(normal, c.right) - b * dot(normal, c.up)) / facing
                         : c.depth0;
    const kernel::Vec2 uv = context.uv->at(c.right * a + c.up * b + c.forward * t);
    const auto texel = [](double x, int size) {
      const double f = x - std::floor(x);
      if (!std::isfinite(f)) return 0;  // coordinates beyond double precision
      return std::clamp(static_cast<int>(f * size), 0, size - 1);
    };
    const int tx = texel(uv.x, image.width);
    const int ty = image.height - 1 - texel(uv.y, image.height);  // rows run top to bottom
    const std::size_t i =
        4 * (static_cast<std::size_t>(ty) * static_cast<std::size_t>(image.width) +
             static_cast<std::size_t>(tx));
    const auto& linear = linear_table();
    return {linear[image.rgba[i]] * tint[0] * light, linear[image.rgba[i + 1]] * tint[1] * light,
            linear[image.rgba[i + 2]] * tint[2] * light};
  }
};

std::uint32_t texel_shade(Context& context, Rgb colour) {
  const auto q = [](float v) {
    return static_cast<std::uint64_t>(std::lround(std::clamp(v, 0.0F, 1.0F) * 4095.0F));
  };
  const std::uint64_t key = static_cast<std::uint64_t>(context.building) << 36 |
                            q(colour[0]) << 24 | q(colour[1]) << 12 | q(colour[2]);
  auto [it, added] = context.texel_shades.try_emplace(key, 0);
  if (added) {
    it->second = context.framebuffer.add_shade(
        {static_cast<float>(q(colour[0])) / 4095.0F, static_cast<float>(q(colour[1])) / 4095.0F,
         static_cast<float>(q(colour[2])) / 4095.0F},
        context.building);
  }
  return it->second;
}

// Ground-plane image of p along the sun direction.
Vec3 shadow_point(const Context& context, Vec3 p) {
  const double t = (p.z - context.ground) / context.sun.z;
  return {p.x - context.sun.x * t, p.y - context.sun.y * t, context.ground};
}

struct Triangle {
  std::array<Vec3, 3> v;
};

// Projects a planar loop onto the coordinate plane most perpendicular to its normal.
Vec2 to_plane(Vec3 p, int axis) {
  if (axis == 2) return {p.x, p.y};
  if (axis == 0) return {p.y, p.z};
  return {p.z, p.x};
}

int dominant_axis(Vec3 n) {
  const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
  if (az >= ax && az >= ay) return 2;
  return ax >= ay ? 0 : 1;
}

// Triangles of one planar face: a fan when the loop is convex, else kernel::triangulate on the
// dominant-plane projection (a fan would cover the notch of a concave face).
void triangulate(const Mesh& mesh, std::size_t face, Vec3 normal, std::vector<Triangle>& out) {
  const auto loop = mesh.face(face);
  const int axis = dominant_axis(normal);
  kernel::Polygon polygon;
  polygon.outer.reserve(loop.size());
  for (std::uint32_t v : loop) polygon.outer.push_back(to_plane(mesh.position(v), axis));
  // A fan from the first vertex covers a convex loop exactly; the projection may mirror it.
  if (loop.size() == 3 || kernel::is_convex(polygon.outer, kernel::Winding::kEither)) {
    for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
      out.push_back({{mesh.position(loop[0]), mesh.position(loop[i]), mesh.position(loop[i + 1])}});
    }
    return;
  }
  // The triangulator adds no vertex: indices are corners of the loop.
  kernel::Triangulation result;
  if (!kernel::triangulate(polygon, result)) return;
  for (const auto& t : result.triangles) {
    if (t[0] >= loop.size() || t[1] >= loop.size() || t[2] >= loop.size()) continue;
    out.push_back(
        {{mesh.position(loop[t[0]]), mesh.position(loop[t[1]]), mesh.position(loop[t[2]])}});
  }
}

// Clips a triangle to z <= cut (Sutherland-Hodgman against one plane); the result is a convex
// polygon of 0, 3 or 4 vertices. Records the section segment where the triangle crosses the cut.
int clip_below(const Triangle& t, double cut, std::array<Vec3, 4>& out,
               std::vector<Vec3>& section) {
  int n = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const Vec3 a = t.v[i], b = t.v[(i + 1) % 3];
    const bool a_in = a.z <= cut, b_in = b.z <= cut;
    if (a_in) out[static_cast<std::size_t>(n++)] = a;
    if (a_in != b_in) {
      const Vec3 p = a + (b - a) * ((cut - a.z) / (b.z - a.z));
      out[static_cast<std::size_t>(n++)] = p;
      section.push_back(p);
    }
  }
  return n;
}

void fill(Context& context, Vec3 a, Vec3 b, Vec3 c, std::uint32_t shade_id, bool cast,
          const TexturedFace* textured) {
  const Camera& camera = context.camera;
  if (textured != nullptr) {
    context.framebuffer.fill_triangle(
        camera.project(a), camera.project(b), camera.project(c),
        [&](float x, float y) { return texel_shade(context, textured->colour_at(x, y)); });
  } else {
    context.framebuffer.fill_triangle(camera.project(a), camera.project(b), camera.project(c),
                                      shade_id);
  }
  if (cast) {
    context.framebuffer.fill_shadow(camera.project(shadow_point(context, a)),
                                    camera.project(shadow_point(context, b)),
                                    camera.project(shadow_point(context, c)));
  }
}

void add_stroke(Context& context, Vec3 a, Vec3 b, Ink ink) {
  context.strokes.push_back({context.camera.project(a), context.camera.project(b), ink});
}

// Per-part data the face and edge passes share.
struct PartData {
  std::vector<Vec3> normals;        // zero for a face that is skipped
  std::vector<std::uint8_t> front;  // 1 when the face's outer side faces the camera
  std::vector<std::uint32_t> weld;  // canonical vertex per vertex (equal positions share one)
  std::vector<Rgb> colour;          // unshaded material colour per face, for outline decisions
  bool closed = false;
};

std::vector<std::uint32_t> weld_ids(const Mesh& mesh) {
  const auto& positions = mesh.positions();
  struct Key {
    std::int64_t x, y, z;
    std::uint32_t vertex;
  };
  std::vector<Key> keys;
  keys.reserve(positions.size());
  std::vector<std::uint32_t> ids(positions.size());
  for (std::uint32_t v = 0; v < positions.size(); ++v) {
    ids[v] = v;
    const Vec3 p = positions[v];
    if (!finite(p) || std::abs(p.x) > 1e9 || std::abs(p.y) > 1e9 || std::abs(p.z) > 1e9) continue;
    keys.push_back({std::llround(p.x / kWeldQuantum), std::llround(p.y / kWeldQuantum),
                    std::llround(p.z / kWeldQuantum), v});
  }
  std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
    return std::tie(a.x, a.y, a.z, a.vertex) < std::tie(b.x, b.y, b.z, b.vertex);
  });
  for (std::size_t i = 1; i < keys.size(); ++i) {
    const Key& a = keys[i - 1];
    const Key& b = keys[i];
    if (a.x == b.x && a.y == b.y && a.z == b.z) ids[b.vertex] = ids[a.vertex];
  }
  return ids;
}

struct EdgeUse {
  std::uint64_t key;  // (smaller canonical vertex << 32) | larger
  std::uint32_t face;
  std::uint32_t from;  // mesh vertex the face's loop leaves the edge from
  std::uint32_t to;
};

std::vector<EdgeUse> edge_uses(const Mesh& mesh, const PartData& data) {
  std::vector<EdgeUse> uses;
  uses.reserve(mesh.triangle_count() + 2 * mesh.face_count());
  for (std::uint32_t f = 0; f < mesh.face_count(); ++f) {
    if (data.normals[f] == Vec3{}) continue;
    const auto loop = mesh.face(f);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const std::uint32_t a = loop[i], b = loop[(i + 1) % loop.size()];
      const std::uint64_t wa = data.weld[a], wb = data.weld[b];
      if (wa == wb) continue;
      uses.push_back({std::min(wa, wb) << 32 | std::max(wa, wb), f, a, b});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return std::tie(x.key, x.face) < std::tie(y.key, y.face);
  });
  return uses;
}

// A part is closed when every edge has exactly two uses in opposite directions; then its back
// faces are hidden behind its front faces and can be culled.
bool is_closed(std::span<const EdgeUse> uses, const PartData& data) {
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    if (j - i != 2 || data.weld[uses[i].from] == data.weld[uses[i + 1].from]) return false;
    i = j;
  }
  return true;
}

// Whether the edge shared by the uses [first, last) is drawn: open boundaries, non-manifold
// edges, silhouettes, creases sharper than the crease angle and changes of colour.
bool outline_edge(const Context& context, const PartData& data, std::span<const EdgeUse> group) {
  if (group.size() != 2) return true;
  const std::uint32_t f = group[0].face, g = group[1].face;
  if (data.front[f] != data.front[g] && group[0].from != group[1].to) {
    // Consistently oriented neighbours on both sides of the view: a silhouette.
    return true;
  }
  Vec3 ng = data.normals[g];
  // Inconsistently oriented neighbours traverse the edge the same way: compare with one flipped.
  if (data.weld[group[0].from] == data.weld[group[1].from]) ng = -ng;
  if (dot(data.normals[f], ng) < context.cos_crease) return true;
  return data.colour[f] != data.colour[g];
}

// Appends the stroke of edge a-b, clipped to z <= cut in cutaway mode.
void edge_stroke(Context& context, Vec3 a, Vec3 b, double cut) {
  if (!std::isnan(cut)) {
    if (a.z > cut && b.z > cut) return;
    if (a.z > cut) a = a + (b - a) * ((cut - a.z) / (b.z - a.z));
    if (b.z > cut) b = b + (a - b) * ((cut - b.z) / (a.z - b.z));
  }
  add_stroke(context, a, b, Ink::kOutline);
}

PartData analyse(const Context& context, const Mesh& mesh) {
  PartData data;
  const std::size_t faces = mesh.face_count();
  data.normals.resize(faces);
  data.front.resize(faces);
  data.colour.resize(faces);
  data.weld = weld_ids(mesh);
  for (std::size_t f = 0; f < faces; ++f) {
    const Vec3 n = drawable(mesh, f) ? kernel::face_normal(mesh, f) : Vec3{};
    data.normals[f] = finite(n) ? n : Vec3{};
    data.front[f] = dot(data.normals[f], context.camera.forward) < 0 ? 1 : 0;
    const auto rgba = view_colour(context, mesh.tag(f));
    data.colour[f] = {rgba[0], rgba[1], rgba[2]};
  }
  return data;
}

void draw_faces(Context& context, const Mesh& mesh, const PartData& data, double cut) {
  const bool cutaway = !std::isnan(cut);
  std::vector<Triangle> triangles;
  std::vector<Vec3> section;
  std::array<Vec3, 4> clipped;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const Vec3 n = data.normals[f];
    if (n == Vec3{}) continue;
    const bool front = data.front[f] != 0;
    // Back faces of a closed part are hidden unless the cut opens the part.
    if (!front && data.closed && !cutaway) continue;
    // Shadows: a closed part's outline is cast by its sun-facing faces alone.
    const bool cast =
        context.options.shadows && (!data.closed || cutaway || dot(n, context.sun) > 0);
    const std::uint32_t shade_id = context.framebuffer.add_shade(
        shade(context, mesh.tag(f), front ? n : -n), context.building);
    triangles.clear();
    triangulate(mesh, f, n, triangles);
    // A face of a part with texture coordinates whose material shows an image samples it.
    std::optional<TexturedFace> textured;
    if (context.uv != nullptr && !triangles.empty()) {
      const shape::Material material = context.scene.material_for(mesh.tag(f));
      const shape::Image* image = material.image.get();
      if (image != nullptr && image->width > 0 && image->height > 0 &&
          image->rgba.size() == 4 * static_cast<std::size_t>(image->width) *
                                    static_cast<std::size_t>(image->height)) {
        textured.emplace(TexturedFace{context, *image, material.rgba,
                                      light_of(context, front ? n : -n), n,
                                      dot(n, triangles.front().v[0])});
      }
    }
    const TexturedFace* texture = textured ? &*textured : nullptr;
    for (const Triangle& t : triangles) {
      if (!cutaway) {
        fill(context, t.v[0], t.v[1], t.v[2], shade_id, cast, texture);
        continue;
      }
      section.clear();
      const int count = clip_below(t, cut, clipped, section);
      for (int i = 1; i + 1 < count; ++i) {
        fill(context, clipped[0], clipped[static_cast<std::size_t>(i)],
             clipped[static_cast<std::size_t>(i + 1)], shade_id, cast, texture);
      }
      if (section.size() == 2 && context.lines) {
        add_stroke(context, section[0], section[1], Ink::kSection);
      }
    }
  }
}

void draw_edges(Context& context, const Mesh& mesh, const PartData& data,
                std::span<const EdgeUse> uses, double cut) {
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    const auto group = uses.subspan(i, j - i);
    if (outline_edge(context, data, group)) {
      edge_stroke(context, mesh.position(group[0].from), mesh.position(group[0].to), cut);
    }
    i = j;
  }
}

void draw_part(Context& context, const Mesh& mesh, double cut) {
  if (mesh.empty()) return;
  PartData data = analyse(context, mesh);
  const std::vector<EdgeUse> uses = edge_uses(mesh, data);
  data.closed = is_closed(uses, data);
  draw_faces(context, mesh, data, cut);
  if (context.options.outlines && context.lines) draw_edges(context, mesh, data, uses, cut);
}

double scene_ground(const shape::Scene& scene) {
  double ground = 1e300;
  for (const shape::Building& building : scene.buildings) {
    for (const shape::Part& part : building.parts) {
      for (std::size_t f = 0; f < part.mesh.face_count(); ++f) {
        if (!drawable(part.mesh, f)) continue;
        for (std::uint32_t v : part.mesh.face(f))
          ground = std::min(ground, part.mesh.position(v).z);
      }
    }
  }
  return ground;
}

// The larger side of the building's screen bounding box, in framebuffer pixels.
double screen_size(const shape::Building& building, const Camera& camera) {
  float x0 = 1e30F, x1 = -1e30F, y0 = 1e30F, y1 = -1e30F;
  for (const shape::Part& part : building.parts) {
    for (Vec3 p : part.mesh.positions()) {
      if (!finite(p)) continue;
      const ScreenPoint s = camera.project(p);
      x0 = std::min(x0, s.x), x1 = std::max(x1, s.x), y0 = std::min(y0, s.y),
      y1 = std::max(y1, s.y);
    }
  }
  return x0 > x1 ? 0.0 : std::max(x1 - x0, y1 - y0);
}

}  // namespace

Camera fit_camera(const shape::Scene& scene, const RenderOptions& options, int width, int height) {
  Camera camera;
  const double azimuth = options.azimuth_deg * kDegree;
  const double elevation = std::clamp(options.elevation_deg, -90.0, 90.0);
  camera.forward = -direction(options.azimuth_deg, elevation);
  // The horizontal right vector does not depend on the elevation, so a plan view (90 degrees)
  // keeps the orientation of the oblique views.
  camera.right = {-std::sin(azimuth), std::cos(azimuth), 0};
  camera.up = kernel::normalized(kernel::cross(camera.right, camera.forward));
  camera.half_width = width / 2.0;
  camera.half_height = height / 2.0;
  double u_min = 1e300, u_max = -1e300, v_min = 1e300, v_max = -1e300;
  double d_min = 1e300, d_max = -1e300;
  for (const shape::Building& building : scene.buildings) {
    for (const shape::Part& part : building.parts) {
      for (std::size_t f = 0; f < part.mesh.face_count(); ++f) {
        if (!drawable(part.mesh, f)) continue;
        for (std::uint32_t vertex : part.mesh.face(f)) {
          const Vec3 p = part.mesh.position(vertex);
          const double u = dot(p, camera.right), v = dot(p, camera.up), d = dot(p, camera.forward);
          u_min = std::min(u_min, u), u_max = std::max(u_max, u);
          v_min = std::min(v_min, v), v_max = std::max(v_max, v);
          d_min = std::min(d_min, d), d_max = std::max(d_max, d);
        }
      }
    }
  }
  if (u_min > u_max) return camera;  // nothing to draw
  camera.u0 = (u_min + u_max) / 2;
  camera.v0 = (v_min + v_max) / 2;
  camera.depth0 = (d_min + d_max) / 2;
  const double usable = 1.0 - 2.0 * options.margin;
  const double span_u = std::max(u_max - u_min, 1e-9), span_v = std::max(v_max - v_min, 1e-9);
  camera.scale = std::min(width * usable / span_u, height * usable / span_v);
  return camera;
}

void draw_scene(const shape::Scene& scene, const RenderOptions& options, const Camera& camera,
                Framebuffer& framebuffer) {
  Context context{scene, options, camera, framebuffer, {}, {}, 0, 1, true, 0, {}};
  context.sun = direction(options.azimuth_deg + kSunAzimuthOffset, kSunElevation);
  context.fill = direction(options.azimuth_deg + kFillAzimuthOffset, kFillElevation);
  context.ground = scene_ground(scene);
  context.cos_crease = std::cos(options.crease_angle_deg * kDegree);
  for (const shape::Building& building : scene.buildings) {
    ++context.building;
    double cut = std::numeric_limits<double>::quiet_NaN();
    if (options.cutaway) {
      cut = std::isnan(options.cut_height) ? auto_cut_height(building) : options.cut_height;
    }
    context.lines = screen_size(building, camera) >= kMinOutlinedSize * options.supersample;
    for (const shape::Part& part : building.parts) {
      context.uv = part.uv ? &*part.uv : nullptr;
      draw_part(context, part.mesh, cut);
    }
  }
  // Strokes go last so their depth test sees every face. Section lines are drawn wider: they are
  // the cut, the strongest line of an architectural drawing.
  const float radius = static_cast<float>(options.outline_width * options.supersample / 2.0);
  const float bias = static_cast<float>(0.75 / camera.scale);
  for (const Stroke& stroke : context.strokes) {
    framebuffer.draw_stroke(stroke, stroke.ink == Ink::kSection ? radius * 1.6F : radius, bias);
  }
}

}  // namespace insula::io::raster
