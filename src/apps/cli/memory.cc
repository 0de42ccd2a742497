#include "apps/cli/memory.h"

#if defined(INSULA_TCMALLOC_LINKED)
#include <gperftools/malloc_extension.h>
#include <gperftools/malloc_extension_c.h>
#include <sys/mman.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#endif

namespace insula::cli {

void release_free_memory() {
#if defined(INSULA_TCMALLOC_LINKED)
  MallocExtension_ReleaseFreeMemory();
#endif
}

#if defined(INSULA_TCMALLOC_LINKED)
namespace {

// tcmalloc's memory from the system in 2 MB-aligned blocks the kernel may back with huge pages
// (MADV_HUGEPAGE: Debian's default THP mode is "madvise"). A first touch of a 4 kB page costs
// 11 to 12 us on the project's machine (a virtual machine), and a district's tiles touch 50,000
// of them (issue 17, docs/PERFORMANCE.md). Where the kernel says no, the block stays as it was.
class HugePageAllocator : public SysAllocator {
 public:
  explicit HugePageAllocator(SysAllocator* fallback) : fallback_(fallback) {}

  void* Alloc(std::size_t size, std::size_t* actual_size, std::size_t alignment) override {
    const std::size_t align = std::max(alignment, kHugePage);
    if (size > kLargest || align > kLargest) return fallback(size, actual_size, alignment);
    const std::size_t rounded = (size + kHugePage - 1) / kHugePage * kHugePage;
    void* mapped = ::mmap(nullptr, rounded + align, PROT_READ | PROT_WRITE,
                          MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (mapped == MAP_FAILED) return fallback(size, actual_size, alignment);
    // The aligned block, the rest of the mapping before and after it given back.
    const auto start = reinterpret_cast<std::uintptr_t>(mapped);
    const std::uintptr_t aligned = (start + align - 1) / align * align;
    if (aligned > start) ::munmap(mapped, aligned - start);
    const std::uintptr_t end = start + rounded + align;
    if (end > aligned + rounded)
      ::munmap(reinterpret_cast<void*>(aligned + rounded), end - aligned - rounded);
    ::madvise(reinterpret_cast<void*>(aligned), rounded, MADV_HUGEPAGE);
    if (actual_size != nullptr) *actual_size = rounded;
    return reinterpret_cast<void*>(aligned);
  }

 private:
  static constexpr std::size_t kHugePage = std::size_t{2} << 20U;
  // Past this the rounding below could overflow: such a request goes to tcmalloc's own.
  static constexpr std::size_t kLargest = std::size_t{1} << 46U;

  void* fallback(std::size_t size, std::size_t* actual_size, std::size_t alignment) {
    return fallback_ != nullptr ? fallback_->Alloc(size, actual_size, alignment) : nullptr;
  }
  SysAllocator* fallback_;
};

}  // namespace
#endif

void use_huge_pages() {
#if defined(INSULA_TCMALLOC_LINKED)
  MallocExtension* extension = MallocExtension::instance();
  static HugePageAllocator allocator(extension->GetSystemAllocator());
  extension->SetSystemAllocator(&allocator);
#endif
}

}  // namespace insula::cli
