#include "apps/cli/s3db_parts.h"

#include <string>

namespace insula::cli {
namespace {

// Whether tag `key` is present with a value other than "no" (S3DB: building=no is not one).
bool tagged(const io::Footprint& footprint, std::string_view key) {
  const std::optional<shape::Value> value = footprint.properties.find(key);
  if (!value || shape::is_null(*value)) return false;
  return shape::to_string(*value) != "no";
}

}  // namespace

std::vector<std::optional<std::size_t>> part_outlines(const io::FootprintSet& set,
                                                      const std::vector<kernel::Overlap>& overlaps,
                                                      const std::vector<bool>& is_part,
                                                      const std::vector<bool>& is_outline) {
  std::vector<std::optional<std::size_t>> outline(set.footprints.size());
  std::vector<double> best(set.footprints.size(), 0);
  for (const kernel::Overlap& overlap : overlaps) {
    for (const auto& [part, candidate] :
         {std::pair{overlap.first, overlap.second}, std::pair{overlap.second, overlap.first}}) {
      if (!is_part[part] || !is_outline[candidate]) continue;
      double part_area = 0;
      for (const kernel::Polygon& polygon : set.footprints[part].polygons) {
        part_area += kernel::area(polygon);
      }
      if (overlap.area < 0.5 * part_area || overlap.area <= best[part]) continue;
      best[part] = overlap.area;
      outline[part] = candidate;
    }
  }
  return outline;
}

std::size_t drop_outlines_with_parts(io::FootprintSet& set) {
  const std::size_t n = set.footprints.size();
  std::vector<bool> is_part(n), is_outline(n);
  bool any_part = false;
  for (std::size_t i = 0; i < n; ++i) {
    is_part[i] = tagged(set.footprints[i], "building:part");
    is_outline[i] = !is_part[i] && tagged(set.footprints[i], "building");
    any_part = any_part || is_part[i];
  }
  if (!any_part) return 0;  // no S3DB parts: nothing to compare (most inputs)
  std::vector<std::vector<kernel::Polygon>> regions;
  regions.reserve(n);
  for (const io::Footprint& footprint : set.footprints) regions.push_back(footprint.polygons);
  const std::vector<std::optional<std::size_t>> outline =
      part_outlines(set, kernel::find_overlaps(regions), is_part, is_outline);
  std::vector<bool> replaced(n, false);
  for (const std::optional<std::size_t>& o : outline) {
    if (o) replaced[*o] = true;
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (replaced[i]) continue;
    if (kept != i) set.footprints[kept] = std::move(set.footprints[i]);
    ++kept;
  }
  set.footprints.resize(kept);
  return n - kept;
}

}  // namespace insula::cli
