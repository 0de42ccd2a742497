// `insula check FILE.bldg`. Being written (see the open issue for the .bldg front-end).
#include <cstdio>
#include <optional>
#include <string>

#include "apps/cli/front_ends.h"

namespace insula::cli {

std::optional<std::string> check_bldg(const base::Source& source, bool /*quiet*/) {
  std::fprintf(stderr, "%s: error: the .bldg front-end cannot check yet\n", source.name().c_str());
  return std::nullopt;
}

}  // namespace insula::cli
