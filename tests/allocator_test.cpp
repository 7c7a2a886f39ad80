#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

#include "cvtmesh/allocator.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace {

// The sanitizers bring their own allocator: GCC says so by macros, Clang by __has_feature.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define CVTMESH_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
#define CVTMESH_SANITIZED 1
#endif
#endif
#if defined(CVTMESH_SANITIZED)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

// A block of an RVD buffer's size (a few MB on a 100k-face input) comes from the heap, not from a
// fresh mapping, and stays there once freed, for the next evaluation to reuse without faulting
// its pages in again. By default glibc maps it, and unmaps it on free.
TEST(Allocator, KeepsFreedBlocksForReuse) {
#if defined(__GLIBC__)
  if (kSanitized) GTEST_SKIP() << "a sanitizer replaces the allocator";
  cvtmesh::keep_freed_memory();
  constexpr std::size_t kBlock = 16 << 20;
  const std::size_t mapped_before = mallinfo2().hblkhd;
  // volatile: the compiler may not drop a block that is only written and freed.
  void* volatile block = std::malloc(kBlock);
  ASSERT_NE(block, nullptr);
  std::memset(static_cast<void*>(block), 1, kBlock);
  EXPECT_LT(mallinfo2().hblkhd, mapped_before + kBlock) << "the block was mapped on its own";
  std::free(static_cast<void*>(block));
  EXPECT_GE(mallinfo2().fordblks, kBlock) << "the freed block went back to the system";
#else
  GTEST_SKIP() << "only glibc's allocator is tuned";
#endif
}

}  // namespace
