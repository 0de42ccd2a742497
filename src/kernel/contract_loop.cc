#include "kernel/contract_loop.h"

#include <algorithm>
#include <cstddef>

namespace insula::kernel {

std::vector<std::vector<std::uint32_t>> contract_loop(std::span<const std::uint32_t> keys) {
  std::vector<std::uint32_t> kept;
  for (std::uint32_t c = 0; c < keys.size(); ++c) {
    if (kept.empty() || keys[kept.back()] != keys[c]) kept.push_back(c);
  }
  while (kept.size() > 1 && keys[kept.back()] == keys[kept.front()]) kept.pop_back();
  std::vector<std::vector<std::uint32_t>> pieces;
  std::vector<std::uint32_t> path;
  std::unordered_map<std::uint32_t, std::size_t> on_path;  // key -> its index in `path`
  for (std::uint32_t c : kept) {
    const auto it = on_path.find(keys[c]);
    if (it == on_path.end()) {
      on_path.emplace(keys[c], path.size());
      path.push_back(c);
      continue;
    }
    // Back at a key already on the path: the corners since then close a piece of their own.
    const std::size_t start = it->second;
    if (path.size() - start >= 3) {
      pieces.emplace_back(path.begin() + static_cast<std::ptrdiff_t>(start), path.end());
    }
    for (std::size_t k = start + 1; k < path.size(); ++k) on_path.erase(keys[path[k]]);
    path.resize(start + 1);
  }
  if (path.size() >= 3) pieces.push_back(std::move(path));
  return pieces;
}

void EdgeUses::add_loop(std::span<const std::uint32_t> loop) {
  for (std::size_t i = 0; i < loop.size(); ++i) add(loop[i], loop[(i + 1) % loop.size()]);
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> EdgeUses::unpaired() const {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  for (const auto& [key, count] : uses_) {
    const auto a = static_cast<std::uint32_t>(key >> 32);
    const auto b = static_cast<std::uint32_t>(key & 0xFFFFFFFFU);
    const auto reverse = uses_.find(std::uint64_t{b} << 32 | a);
    if (count != 1 || reverse == uses_.end() || reverse->second != 1) out.emplace_back(a, b);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace insula::kernel
