// `insula build FILE.bldg`. Being written (see the open issue for the .bldg front-end).
#include <cstdio>

#include "apps/cli/exit_codes.h"
#include "apps/cli/front_ends.h"

namespace insula::cli {

int build_bldg(const BuildOptions& options) {
  std::fprintf(stderr, "insula: %s: the .bldg front-end cannot build yet\n", options.input.c_str());
  return kExitInternal;
}

}  // namespace insula::cli
