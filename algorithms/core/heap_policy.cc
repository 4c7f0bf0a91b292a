#include "algorithms/core/heap_policy.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace roofsweep {

void KeepLargeAllocationsOnHeap() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
  mallopt(M_TRIM_THRESHOLD, 512 * 1024 * 1024);
#endif
}

}  // namespace roofsweep
