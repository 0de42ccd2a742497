#pragma once

namespace insula::cli {

inline constexpr int kExitDone = 0;
inline constexpr int kExitInput = 1;
inline constexpr int kExitUsage = 2;
inline constexpr int kExitInternal = 3;

}  // namespace insula::cli
