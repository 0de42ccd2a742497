#include "apps/cli/memory.h"

#if defined(INSULA_TCMALLOC_LINKED)
#include <gperftools/malloc_extension_c.h>
#endif

namespace insula::cli {

void release_free_memory() {
#if defined(INSULA_TCMALLOC_LINKED)
  MallocExtension_ReleaseFreeMemory();
#endif
}

}  // namespace insula::cli
