#include "apps/cli/s3db_parts.h"

#include <algorithm>

#include "base/tag_numbers.h"
#include "io/map_areas.h"

namespace insula::cli {

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

namespace {

// Whether an S3DB building or part starts above the ground.
bool elevated(const io::Footprint& footprint) {
  const auto positive = [&](std::string_view key, auto parse) {
    const std::optional<shape::Value> value = footprint.properties.find(key);
    if (!value || shape::is_null(*value)) return false;
    if (const double* number = std::get_if<double>(&*value)) return *number > 0;
    const std::optional<double> parsed = parse(shape::to_string(*value));
    return parsed && *parsed > 0;
  };
  return positive("min_height", base::parse_length) ||
         positive("building:min_level", base::parse_levels);
}

}  // namespace

LotsLeftOut leave_out_for_lots(io::FootprintSet& set) {
  const std::size_t n = set.footprints.size();
  std::vector<bool> is_part(n), is_outline(n), leave(n, false);
  bool any_part = false;
  LotsLeftOut out;
  for (std::size_t i = 0; i < n; ++i) {
    const io::Footprint& footprint = set.footprints[i];
    is_part[i] = io::tagged(footprint.properties, "building:part");
    is_outline[i] = !is_part[i] && io::tagged(footprint.properties, "building");
    any_part = any_part || is_part[i];
    if ((is_part[i] || is_outline[i]) && elevated(footprint)) {
      leave[i] = true;
      ++out.elevated;
      is_part[i] = false;  // it does not stand in its outline: one of only such parts stays
      is_outline[i] = false;
    }
  }
  if (any_part) {  // no S3DB parts (most inputs): no outline to compare
    std::vector<std::vector<kernel::Polygon>> regions;
    regions.reserve(n);
    for (const io::Footprint& footprint : set.footprints) regions.push_back(footprint.polygons);
    const std::vector<std::optional<std::size_t>> outline =
        part_outlines(set, kernel::find_overlaps(regions), is_part, is_outline);
    for (const std::optional<std::size_t>& o : outline) {
      if (o && !leave[*o]) {
        leave[*o] = true;
        ++out.outlines;
      }
    }
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (leave[i]) continue;
    if (kept != i) set.footprints[kept] = std::move(set.footprints[i]);
    ++kept;
  }
  set.footprints.resize(kept);
  return out;
}

}  // namespace insula::cli
