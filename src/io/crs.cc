// PROJ behind io/crs.h. Every call makes its own PJ_CONTEXT: contexts are not thread-safe, the
// reader calls here a few times per file, and a context costs well under a millisecond once
// PROJ's database is cached by the operating system. Logging is off: the reader never prints,
// it reports.
#include "io/crs.h"

#include <proj.h>

#include <cmath>
#include <limits>
#include <memory>

namespace insula::io {
namespace {

struct ContextDeleter {
  void operator()(PJ_CONTEXT* c) const { proj_context_destroy(c); }
};
struct PjDeleter {
  void operator()(PJ* p) const { proj_destroy(p); }
};
using Context = std::unique_ptr<PJ_CONTEXT, ContextDeleter>;
using Pj = std::unique_ptr<PJ, PjDeleter>;

Context make_context() {
  Context ctx(proj_context_create());
  if (ctx) {
    proj_log_level(ctx.get(), PJ_LOG_NONE);
    proj_context_set_enable_network(ctx.get(), 0);
  }
  return ctx;
}

std::string upper(std::string text) {
  for (char& c : text) {
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 32);
  }
  return text;
}

// The horizontal part of a compound CRS (a 2D CRS is its own).
Pj horizontal(PJ_CONTEXT* ctx, Pj crs) {
  if (proj_get_type(crs.get()) == PJ_TYPE_COMPOUND_CRS) {
    return Pj(proj_crs_get_sub_crs(ctx, crs.get(), 0));
  }
  return crs;
}

// Web Mercator under the unofficial codes web maps used before EPSG:3857 existed.
std::string official_name(const std::string& name) {
  for (const char* alias : {"EPSG:900913", "EPSG:102100", "EPSG:102113", "EPSG:3785"}) {
    if (name == alias) return "EPSG:3857";
  }
  return name;
}

// Normal-aspect Mercator projections (Web Mercator, EPSG methods 1024, 1026, 9804, 9805) keep
// angles but scale lengths by 1 / cos(latitude): their meters are not ground meters.
bool is_mercator(PJ_CONTEXT* ctx, PJ* crs) {
  const Pj op(proj_crs_get_coordoperation(ctx, crs));
  const char* method = nullptr;
  if (!op || !proj_coordoperation_get_method_info(ctx, op.get(), &method, nullptr, nullptr) ||
      method == nullptr) {
    return false;
  }
  const std::string text = upper(method);
  return text.find("MERCATOR") != std::string::npos &&
         text.find("TRANSVERSE") == std::string::npos && text.find("OBLIQUE") == std::string::npos;
}

}  // namespace

std::optional<CrsInfo> describe_crs(const std::string& name, std::string& error) {
  const Context ctx = make_context();
  if (!ctx) {
    error = "PROJ could not start";
    return std::nullopt;
  }
  const std::string official = official_name(upper(name));
  Pj crs(proj_create(ctx.get(), official.c_str()));
  if (crs && !proj_is_crs(crs.get())) crs.reset();
  if (!crs) {
    error = "PROJ does not know the CRS '" + name + "'";
    return std::nullopt;
  }
  crs = horizontal(ctx.get(), std::move(crs));
  const PJ_TYPE type = crs ? proj_get_type(crs.get()) : PJ_TYPE_UNKNOWN;
  const bool geographic = type == PJ_TYPE_GEOGRAPHIC_2D_CRS || type == PJ_TYPE_GEOGRAPHIC_3D_CRS;
  if (!geographic && type != PJ_TYPE_PROJECTED_CRS) {
    error = "'" + name + "' is neither a geographic nor a projected CRS";
    return std::nullopt;
  }
  const Pj cs(proj_crs_get_coordinate_system(ctx.get(), crs.get()));
  const char* unit = nullptr;
  double to_unit = 0;
  if (!cs || !proj_cs_get_axis_info(ctx.get(), cs.get(), 0, nullptr, nullptr, nullptr, &to_unit,
                                    &unit, nullptr, nullptr)) {
    error = "PROJ gives no axis unit for '" + name + "'";
    return std::nullopt;
  }
  CrsInfo info;
  info.name = official;
  const char* title = proj_get_name(crs.get());
  info.title = title != nullptr ? title : "";
  info.geographic = geographic;
  info.unit = unit != nullptr ? unit : "";
  info.mercator = !geographic && is_mercator(ctx.get(), crs.get());
  info.metric = !geographic && to_unit == 1.0 && !info.mercator;
  return info;
}

std::string buildable_crs(const std::string& name) {
  std::string error;
  const std::optional<CrsInfo> info = describe_crs(name, error);
  if (!info) return error;
  if (info->metric) return "";
  const std::string what = info->name + " (" + info->title + ")";
  if (info->geographic) return what + " is geographic (degrees); name a projected CRS in meters";
  if (info->mercator) {
    return what +
           " is a Mercator projection, whose meters grow with latitude (1 / cos(latitude)); "
           "name a projected CRS in ground meters";
  }
  return what + " measures in " + info->unit + "; name a projected CRS in meters";
}

std::string utm_crs(double lon, double lat) {
  const double wrapped = lon - 360.0 * std::floor((lon + 180.0) / 360.0);
  int zone = static_cast<int>(std::floor((wrapped + 180.0) / 6.0)) + 1;
  zone = zone < 1 ? 1 : (zone > 60 ? 60 : zone);
  return "EPSG:" + std::to_string((lat < 0 ? 32700 : 32600) + zone);
}

std::string reproject(const std::string& from, const std::string& to,
                      std::vector<kernel::Vec2>& points) {
  const Context ctx = make_context();
  if (!ctx) return "PROJ could not start";
  const Pj raw(proj_create_crs_to_crs(ctx.get(), from.c_str(), to.c_str(), nullptr));
  if (!raw) return "PROJ finds no transformation from " + from + " to " + to;
  // GeoJSON writes longitude first whatever the CRS definition says (EPSG:4326 is latitude
  // first); the visualization order is east, north for every CRS.
  const Pj op(proj_normalize_for_visualization(ctx.get(), raw.get()));
  if (!op) return "PROJ finds no transformation from " + from + " to " + to;
  if (points.empty()) return "";
  constexpr std::size_t kStride = sizeof(kernel::Vec2);
  static_assert(kStride == 2 * sizeof(double));
  proj_trans_generic(op.get(), PJ_FWD, &points[0].x, kStride, points.size(), &points[0].y, kStride,
                     points.size(), nullptr, 0, 0, nullptr, 0, 0);
  for (kernel::Vec2& p : points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      p = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    }
  }
  return "";
}

std::string to_ecef(const std::string& crs, std::vector<kernel::Vec3>& points) {
  const Context ctx = make_context();
  if (!ctx) return "PROJ could not start";
  const Pj raw(proj_create_crs_to_crs(ctx.get(), crs.c_str(), "EPSG:4978", nullptr));
  if (!raw) return "PROJ finds no transformation from " + crs + " to EPSG:4978";
  const Pj op(proj_normalize_for_visualization(ctx.get(), raw.get()));
  if (!op) return "PROJ finds no transformation from " + crs + " to EPSG:4978";
  if (points.empty()) return "";
  constexpr std::size_t kStride = sizeof(kernel::Vec3);
  static_assert(kStride == 3 * sizeof(double));
  const std::size_t n = points.size();
  proj_trans_generic(op.get(), PJ_FWD, &points[0].x, kStride, n, &points[0].y, kStride, n,
                     &points[0].z, kStride, n, nullptr, 0, 0);
  for (kernel::Vec3& p : points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      p = {nan, nan, nan};
    }
  }
  return "";
}

std::vector<std::array<double, 16>> ecef_frames(const std::string& crs,
                                                const std::vector<kernel::Vec3>& at,
                                                std::string& error) {
  // Central differences over +-1 m: ECEF doubles keep ~1e-9 m, and the projection's curvature
  // over a metre is far below that.
  constexpr std::size_t kSamples = 7;
  std::vector<kernel::Vec3> points;
  points.reserve(kSamples * at.size());
  for (const kernel::Vec3 p : at) {
    points.insert(points.end(), {p, p + kernel::Vec3{1, 0, 0}, p - kernel::Vec3{1, 0, 0},
                                 p + kernel::Vec3{0, 1, 0}, p - kernel::Vec3{0, 1, 0},
                                 p + kernel::Vec3{0, 0, 1}, p - kernel::Vec3{0, 0, 1}});
  }
  error = to_ecef(crs, points);
  if (!error.empty()) return {};
  std::vector<std::array<double, 16>> frames;
  frames.reserve(at.size());
  for (std::size_t i = 0; i < at.size(); ++i) {
    const kernel::Vec3* sample = &points[kSamples * i];
    for (std::size_t k = 0; k < kSamples; ++k) {
      if (std::isfinite(sample[k].x)) continue;
      error = "PROJ cannot place the point (" + std::to_string(at[i].x) + ", " +
              std::to_string(at[i].y) + ") of " + crs + " on the globe";
      return {};
    }
    std::array<double, 16>& m = frames.emplace_back();
    for (std::size_t axis = 0; axis < 3; ++axis) {
      const kernel::Vec3 step = (sample[1 + 2 * axis] - sample[2 + 2 * axis]) * 0.5;
      m[4 * axis + 0] = step.x;
      m[4 * axis + 1] = step.y;
      m[4 * axis + 2] = step.z;
    }
    m[12] = sample[0].x;
    m[13] = sample[0].y;
    m[14] = sample[0].z;
    m[15] = 1;
  }
  return frames;
}

}  // namespace insula::io
