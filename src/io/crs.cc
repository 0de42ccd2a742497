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

}  // namespace insula::io
