#include "apps/cli/s3db_parts.h"

#include <algorithm>
#include <array>
#include <set>
#include <string>

#include "base/tag_numbers.h"

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
    is_part[i] = tagged(footprint, "building:part");
    is_outline[i] = !is_part[i] && tagged(footprint, "building");
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

std::optional<std::string> non_building_area(const io::Footprint& footprint) {
  if (tagged(footprint, "building") || tagged(footprint, "building:part")) return std::nullopt;
  // A structure mapped without a building tag (a multi-storey car park, a hangar, a shelter)
  // still says so by its height, levels or roof tags, or by its value.
  const shape::AttributeMap properties = footprint.properties.map();
  const bool structure =
      std::any_of(properties.begin(), properties.end(), [](const auto& property) {
        const std::string_view key = property.first;
        return key == "height" || key == "min_height" || key.starts_with("building:") ||
               key.starts_with("roof:");
      });
  if (structure) return std::nullopt;
  // Into `properties`, which outlives every use.
  const auto text_of = [&](std::string_view key) -> const std::string* {
    const auto found = properties.find(std::string(key));
    return found == properties.end() ? nullptr : std::get_if<std::string>(&found->second);
  };
  for (const auto& [key, value] :
       {std::pair{"parking", "multi-storey"}, std::pair{"aeroway", "hangar"},
        std::pair{"aeroway", "terminal"}, std::pair{"amenity", "shelter"}}) {
    if (const std::string* text = text_of(key); text != nullptr && *text == value) {
      return std::nullopt;
    }
  }
  // OSM's keys for areas that are land, water, ways, grounds or pitches rather than structures;
  // man_made, historic and tourism are left out, since towers, castles and huts are mapped with
  // them alone. Only text values count: a register's numeric column of one of these names
  // (an `area` in m2) says nothing of the kind, and `area` counts only as OSM's `area=yes`.
  static constexpr std::array<std::string_view, 16> kAreaKeys{
      "landuse",  "natural", "leisure",    "amenity",  "highway", "area:highway",
      "waterway", "water",   "railway",    "boundary", "aeroway", "military",
      "golf",     "sport",   "piste:type", "barrier"};
  for (std::string_view key : kAreaKeys) {
    const std::string* text = text_of(key);
    if (text != nullptr && !text->empty() && *text != "no") return std::string(key) + "=" + *text;
  }
  const std::string* area = text_of("area");
  if (area != nullptr && *area == "yes") return "area=yes";
  return std::nullopt;
}

NonBuildingsLeftOut leave_out_non_buildings(io::FootprintSet& set) {
  NonBuildingsLeftOut out;
  // Only a map export, where buildings carry their tag: a register whose text column happens to
  // be called `landuse` or `amenity` keeps every footprint.
  const bool tagged_export = std::any_of(
      set.footprints.begin(), set.footprints.end(),
      [](const io::Footprint& f) { return tagged(f, "building") || tagged(f, "building:part"); });
  if (!tagged_export) return out;
  std::set<std::string> seen;
  std::erase_if(set.footprints, [&](const io::Footprint& footprint) {
    std::optional<std::string> tag = non_building_area(footprint);
    if (!tag) return false;
    ++out.count;
    if (seen.insert(*tag).second) out.tags.push_back(std::move(*tag));
    return true;
  });
  return out;
}

}  // namespace insula::cli
