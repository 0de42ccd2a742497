// Issue 19 item 6, "no simple footprint without its roof": every roof type over thousands of
// rotated rectangles and near-rectangles with coordinates rounded to millimetres (as national
// registers publish them), and over rotated L, T, U and star shapes, gives one closed,
// consistently oriented shell of positive volume with the asked roof (or, where the shape is not
// defined for the footprint, its documented fallback: docs/kernel-roofs.md, "Fallbacks").
//
// Release runs 10,000 rectangles and 1,200 other shapes; under AddressSanitizer (about ten times
// slower) 1,000 and 160, so the sanitizer lane stays within its time budget
// (docs/kernel-roofs.md, "Near-rectangles").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "kernel/mass.h"

namespace insula::kernel {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr int kRectangles = 1000;
constexpr int kEachShape = 40;
#else
constexpr int kRectangles = 10000;
constexpr int kEachShape = 300;
#endif

constexpr double kPi = 3.14159265358979323846;

double round_mm(double v) {
  return std::round(v * 1000) / 1000;
}

// `outline` (counter-clockwise, local) rotated by `angle`, moved to `at` and rounded to mm.
Polygon place(const Ring& outline, double angle, Vec2 at) {
  Polygon p;
  const double c = std::cos(angle), s = std::sin(angle);
  for (const Vec2& q : outline) {
    p.outer.push_back({round_mm(at.x + c * q.x - s * q.y), round_mm(at.y + s * q.x + c * q.y)});
  }
  return p;
}

struct Sampler {
  std::mt19937_64 rng{19};
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
  }
  // Local positions (a few km from the origin a reader picks), and georeferenced ones left as
  // they are in a national grid.
  Vec2 position() {
    switch (rng() % 3) {
      case 0:
        return {uniform(-50, 50), uniform(-50, 50)};
      case 1:
        return {uniform(-5000, 5000), uniform(-5000, 5000)};
      default:
        return {uniform(1e5, 3e5), uniform(3e5, 6e5)};
    }
  }
};

std::string describe(const Polygon& p) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(3);
  for (const Vec2& q : p.outer) out << " (" << q.x << ", " << q.y << ")";
  return out.str();
}

// Builds every roof over `footprint` and checks the shell; `allowed(asked)` lists the types that
// may be built.
template <typename Allowed>
int check_all(const Polygon& footprint, const char* shape, Allowed allowed) {
  int failures = 0;
  for (RoofType asked : kRoofTypes) {
    MassSpec spec;
    spec.roof = asked;
    spec.wall_height = 6;
    const MassResult r = build_mass(footprint, spec);
    const MeshCheck c = check(r.mesh);
    const std::set<RoofType> ok = allowed(asked);
    const bool good = r.status != MassStatus::kFailed && c.closed && c.oriented &&
                      volume(r.mesh) > 0 && ok.count(r.roof) == 1 &&
                      (r.roof != asked || r.status == MassStatus::kOk);
    if (!good && ++failures <= 3) {
      ADD_FAILURE() << shape << " " << roof_type_name(asked) << " built " << roof_type_name(r.roof)
                    << " closed " << c.closed << " oriented " << c.oriented << " boundary "
                    << c.boundary_edges << " message '" << r.message << "' footprint"
                    << describe(footprint);
    }
  }
  return failures;
}

TEST(RoofSweep, EveryRoofOnRotatedRectanglesRoundedToMillimetres) {
  Sampler s;
  int failed = 0;
  const auto exactly = [](RoofType asked) { return std::set<RoofType>{asked}; };
  for (int i = 0; i < kRectangles; ++i) {
    const double w = s.uniform(3, 15);
    const double l = i % 4 == 0 ? w * s.uniform(1, 1.08) : s.uniform(3, 40);  // some near squares
    Ring outline{{0, 0}, {l, 0}, {l, w}, {0, w}};
    const bool near = i % 2 == 1;  // corners moved by up to 3 cm
    if (near) {
      for (Vec2& q : outline) q += Vec2{s.uniform(-0.03, 0.03), s.uniform(-0.03, 0.03)};
    }
    const Polygon p = place(outline, s.uniform(0, 2 * kPi), s.position());
    failed += check_all(p, near ? "near-rectangle" : "rectangle", exactly) > 0;
    if (failed > 5) break;
  }
  EXPECT_EQ(failed, 0);
}

// Rectangles whose long sides came out of the rounding less than 1.5e-6 rad from antiparallel:
// the convex wavefront took them for parallel, ended the ridge at the first end's event and left
// a sliver of the roof open at the other end (found by the sweep above; docs/kernel-roofs.md,
// "Near-rectangles").
TEST(RoofSweep, AlmostAntiparallelLongSidesCloseTheRoof) {
  const std::vector<Polygon> footprints = {
      {{{2935.895, 4140.303}, {2957.486, 4140.909}, {2957.364, 4145.282}, {2935.772, 4144.676}},
       {}},
      {{{339.377, 2935.256}, {339.733, 2951.239}, {336.338, 2951.314}, {335.982, 2935.332}}, {}},
      {{{1231.560, 4793.956}, {1232.237, 4816.326}, {1227.887, 4816.458}, {1227.210, 4794.087}},
       {}},
      {{{176153.673, 248418.206},
        {176175.264, 248418.812},
        {176175.142, 248423.185},
        {176153.550, 248422.579}},
       {}}};
  for (const Polygon& p : footprints) {
    EXPECT_EQ(check_all(p, "rectangle", [](RoofType asked) { return std::set<RoofType>{asked}; }),
              0);
  }
}

Ring l_outline(double a, double b, double wa, double wb) {
  return {{0, 0}, {a, 0}, {a, wa}, {wb, wa}, {wb, b}, {0, b}};
}
Ring t_outline(double bar, double depth, double stem, double length) {
  const double x0 = (bar - stem) / 2;
  return {{x0, 0},       {x0 + stem, 0},        {x0 + stem, length},
          {bar, length}, {bar, length + depth}, {0, length + depth},
          {0, length},   {x0, length}};
}
Ring u_outline(double width, double depth, double arm, double base) {
  return {{0, 0},      {width, 0},   {width, depth}, {width - arm, depth}, {width - arm, base},
          {arm, base}, {arm, depth}, {0, depth}};
}
Ring star_outline(int points, double outer, double inner) {
  Ring r;
  for (int k = 0; k < 2 * points; ++k) {
    const double radius = k % 2 == 0 ? outer : inner;
    const double angle = kPi * k / points;
    r.push_back({radius * std::cos(angle), radius * std::sin(angle)});
  }
  return r;
}

// The documented fallbacks of shapes a concave outline does not define.
std::set<RoofType> concave_allowed(RoofType asked, bool star) {
  // A star's tips have no antiparallel neighbours to end a ridge: its gables become hips.
  const RoofType gable = star ? RoofType::kHip : RoofType::kGable;
  switch (asked) {
    case RoofType::kPyramid:
      return {RoofType::kHip};
    case RoofType::kGable:
    case RoofType::kHalfHipped:
    case RoofType::kSaltbox:
    case RoofType::kRound:
      return {gable};
    case RoofType::kGambrel:
      return {RoofType::kMansard};
    case RoofType::kDome:
    case RoofType::kOnion:
      // A star is star-shaped about its centre; an L, T or U may or may not be about its centroid.
      return star ? std::set<RoofType>{asked} : std::set<RoofType>{asked, RoofType::kHip};
    default:
      return {asked};
  }
}

TEST(RoofSweep, EveryRoofOnRotatedLTUAndStarShapes) {
  Sampler s;
  int failed = 0;
  for (int i = 0; i < 4 * kEachShape; ++i) {
    Ring outline;
    const char* shape = "";
    switch (i % 4) {
      case 0:
        shape = "L";
        outline = l_outline(s.uniform(8, 20), s.uniform(8, 20), s.uniform(3, 7), s.uniform(3, 7));
        break;
      case 1:
        shape = "T";
        outline = t_outline(s.uniform(12, 24), s.uniform(4, 8), s.uniform(4, 8), s.uniform(4, 12));
        break;
      case 2:
        shape = "U";
        outline = u_outline(s.uniform(14, 24), s.uniform(10, 18), s.uniform(3, 6), s.uniform(3, 6));
        break;
      default:
        shape = "star";
        outline =
            star_outline(5 + static_cast<int>(s.rng() % 4), s.uniform(6, 12), s.uniform(3, 5));
        break;
    }
    const bool star = i % 4 == 3;
    const Polygon p = place(outline, s.uniform(0, 2 * kPi), s.position());
    failed += check_all(p, shape, [&](RoofType asked) { return concave_allowed(asked, star); }) > 0;
    if (failed > 5) break;
  }
  EXPECT_EQ(failed, 0);
}

// Gambrel, half-hipped and saltbox with a 0.5 m overhang (docs/kernel-roofs.md, "Overhang") over
// rotated rectangles, near-rectangles and skewed quadrilaterals rounded to millimetres, a quarter
// with one more nearly straight vertex on a slope side or an end (OpenStreetMap outlines have
// them): closed, the asked type with its overhang.
TEST(RoofSweep, QuadrilateralShapesWithOverhang) {
  Sampler s;
  int failed = 0;
  int flush = 0;
  const int n = kRectangles / 10;
  for (int i = 0; i < n; ++i) {
    const double w = s.uniform(4, 12);
    const double l = s.uniform(w, 30);
    Ring outline{{0, 0}, {l, 0}, {l, w}, {0, w}};
    const double jitter = i % 3 == 0 ? 0.0 : i % 3 == 1 ? 0.03 : 0.08 * w;  // last: skewed
    for (Vec2& q : outline) q += Vec2{s.uniform(-jitter, jitter), s.uniform(-jitter, jitter)};
    const bool extra = i % 4 == 3;
    if (extra) {  // a vertex 5 cm from a corner, the outline turning there by under 2 degrees
      const std::size_t e = i % 8 == 3 ? 0 : 1;  // on a long side (a slope) or an end
      const Vec2 a = outline[e], b = outline[e + 1];
      const Vec2 d = normalized(b - a);
      outline.insert(outline.begin() + static_cast<std::ptrdiff_t>(e) + 1,
                     a + d * 0.05 + perp(d) * s.uniform(-1.5e-3, 1.5e-3));
    }
    const Polygon p = place(outline, s.uniform(0, 2 * kPi), s.position());
    for (RoofType asked : {RoofType::kGambrel, RoofType::kHalfHipped, RoofType::kSaltbox}) {
      MassSpec spec;
      spec.roof = asked;
      spec.wall_height = 6;
      spec.overhang = 0.5;
      const MassResult r = build_mass(p, spec);
      const MeshCheck c = check(r.mesh);
      int soffits = 0;
      double off_plane = 0;  // every face planar
      for (std::size_t f = 0; f < r.mesh.face_count(); ++f) {
        soffits += r.mesh.tag(f).semantic == SemanticClass::kOuterCeilingSurface;
        const Vec3 normal = face_normal(r.mesh, f);
        const Vec3 p0 = r.mesh.position(r.mesh.face(f)[0]);
        for (std::uint32_t v : r.mesh.face(f)) {
          off_plane = std::max(off_plane, std::abs(dot(r.mesh.position(v) - p0, normal)));
        }
      }
      flush += r.message.find("built without overhang") != std::string::npos;
      const bool good = r.status == MassStatus::kOk && c.closed && c.oriented &&
                        c.components == 1 && volume(r.mesh) > 0 && r.roof == asked &&
                        soffits >= 2 && off_plane < 1e-6;
      if (!good && ++failed <= 3) {
        ADD_FAILURE() << roof_type_name(asked) << " built " << roof_type_name(r.roof) << " closed "
                      << c.closed << " oriented " << c.oriented << " boundary " << c.boundary_edges
                      << " soffits " << soffits << " off plane " << off_plane << " message '"
                      << r.message << "' footprint" << describe(p);
      }
    }
    if (failed > 5) break;
  }
  EXPECT_EQ(failed, 0);
  EXPECT_EQ(flush, 0);
}

}  // namespace
}  // namespace insula::kernel
