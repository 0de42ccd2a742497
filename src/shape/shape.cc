#include "shape/shape.h"

namespace insula::shape {

bool Region::contains(kernel::Vec3 local, double tolerance) const {
  return local.x >= min.x - tolerance && local.x <= max.x + tolerance &&
         local.y >= min.y - tolerance && local.y <= max.y + tolerance &&
         local.z >= min.z - tolerance && local.z <= max.z + tolerance;
}

RegionPlacement sample(const Region& region, Rng& rng) {
  RegionPlacement p;
  p.position = {rng.uniform(region.min.x, region.max.x), rng.uniform(region.min.y, region.max.y),
                rng.uniform(region.min.z, region.max.z)};
  p.degrees = {rng.uniform(region.min_degrees.x, region.max_degrees.x),
               rng.uniform(region.min_degrees.y, region.max_degrees.y),
               rng.uniform(region.min_degrees.z, region.max_degrees.z)};
  return p;
}

}  // namespace insula::shape
