// `insula build FILE.cga`. Being written (see the open issue for the .cga front-end).
#include <cstdio>

#include "apps/cli/exit_codes.h"
#include "apps/cli/front_ends.h"

namespace insula::cli {

int build_cga(const BuildOptions& options) {
  std::fprintf(stderr, "insula: %s: the .cga front-end cannot build yet\n", options.input.c_str());
  return kExitInternal;
}

}  // namespace insula::cli
