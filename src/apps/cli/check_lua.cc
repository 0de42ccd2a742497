// `insula check FILE.lua`. Being written (see the open issue for the .lua front-end).
#include <cstdio>
#include <optional>
#include <string>

#include "apps/cli/front_ends.h"

namespace insula::cli {

std::optional<std::string> check_lua(const base::Source& source, bool /*quiet*/) {
  std::fprintf(stderr, "%s: error: the .lua front-end cannot check yet\n", source.name().c_str());
  return std::nullopt;
}

}  // namespace insula::cli
