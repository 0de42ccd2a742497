// Offset and setback of flat shapes (CGA offset and setback). Waiting for kernel boolean2d.h.
#include "shape/ops.h"

namespace insula::shape {

std::vector<Operation> offset_operations() {
  return {};
}

}  // namespace insula::shape
