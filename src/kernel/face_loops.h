// Face loops as lists of vertex indices, and joining two of them along the edge they share (mesh
// cleanup's coplanar merge, the convex partition's diagonal removal).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

namespace insula::kernel {

using IndexLoop = std::vector<std::uint32_t>;

// The one loop covering `a` and `b` without their common edge {x, y}: `a` must run along it one
// way and `b` the other, and they must have no other vertex in common (joining would pinch the
// loop). Nullopt otherwise.
std::optional<IndexLoop> join_along(const IndexLoop& a, const IndexLoop& b, std::uint32_t x,
                                    std::uint32_t y);

}  // namespace insula::kernel
