#include "kernel/face_loops.h"

#include <algorithm>
#include <utility>

namespace insula::kernel {

namespace {

std::size_t position(const IndexLoop& loop, std::uint32_t v) {
  return static_cast<std::size_t>(std::find(loop.begin(), loop.end(), v) - loop.begin());
}

bool runs(const IndexLoop& loop, std::uint32_t from, std::uint32_t to) {
  const std::size_t i = position(loop, from);
  return i < loop.size() && loop[(i + 1) % loop.size()] == to;
}

}  // namespace

std::optional<IndexLoop> join_along(const IndexLoop& a, const IndexLoop& b, std::uint32_t x,
                                    std::uint32_t y) {
  std::size_t shared = 0;
  for (std::uint32_t v : a) shared += std::count(b.begin(), b.end(), v) > 0 ? 1 : 0;
  if (shared != 2) return std::nullopt;
  if (!runs(a, x, y)) std::swap(x, y);
  if (!runs(a, x, y) || !runs(b, y, x)) return std::nullopt;
  // `a` from y round to x, then `b`'s vertices strictly between x and y.
  IndexLoop out;
  for (std::size_t k = 0, i = position(a, y); k < a.size(); ++k)
    out.push_back(a[(i + k) % a.size()]);
  for (std::size_t k = 1, i = position(b, x); k + 1 < b.size(); ++k) {
    out.push_back(b[(i + k) % b.size()]);
  }
  return out;
}

}  // namespace insula::kernel
