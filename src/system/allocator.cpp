#include "cvtmesh/allocator.hpp"

#include <cstdlib>  // defines __GLIBC__ where glibc is the C library

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace cvtmesh {

void keep_freed_memory() {
#if defined(__GLIBC__)
  // Blocks up to 32 MiB, glibc's largest threshold on 64-bit, come from the heap rather than
  // from mmap; free memory at the heap's top goes back to the system past 256 MiB only. Lower
  // thresholds measured: 4 MiB and 8 MiB kept igea's peak as it was but lost half the gain there.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
#endif
}

}  // namespace cvtmesh
