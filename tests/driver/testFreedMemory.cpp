// What the allocator does with freed memory in a run (driver/FreedMemory.hpp).
#include "driver/FreedMemory.hpp"

#include <gtest/gtest.h>
#include <malloc.h>

#include <cstdlib>
#include <cstring>

namespace {

// AddressSanitizer's allocator takes no mallopt settings (GCC and clang say so differently).
#if defined(__SANITIZE_ADDRESS__)
constexpr bool glibcAllocates = false;
#elif defined(__has_feature)
constexpr bool glibcAllocates = !__has_feature(address_sanitizer);
#else
constexpr bool glibcAllocates = true;
#endif

}  // namespace

TEST(FreedMemory, ABlockOfMegabytesComesFromTheHeapAndStaysThereWhenFreed) {
    if (!glibcAllocates) GTEST_SKIP() << "not glibc's allocator";
    unsetenv("GLIBC_TUNABLES");
    unsetenv("MALLOC_MMAP_THRESHOLD_");
    unsetenv("MALLOC_TRIM_THRESHOLD_");
    ASSERT_TRUE(sph::keepFreedMemoryForReuse());
    constexpr std::size_t bytes = 8 << 20;  // a 2D run's velocity at half a million particles
    const std::size_t mappedBefore = mallinfo2().hblkhd;
    void* block = std::malloc(bytes);
    ASSERT_NE(block, nullptr);
    std::memset(block, 1, bytes);
    EXPECT_EQ(mallinfo2().hblkhd, mappedBefore);  // not mapped for itself
    std::free(block);
    EXPECT_GE(mallinfo2().fordblks, bytes);  // kept, free for the next block
}

TEST(FreedMemory, SettingsTheUserChoseAreKept) {
    setenv("MALLOC_TRIM_THRESHOLD_", "131072", 1);
    EXPECT_FALSE(sph::keepFreedMemoryForReuse());
    unsetenv("MALLOC_TRIM_THRESHOLD_");
    setenv("GLIBC_TUNABLES", "glibc.malloc.mmap_threshold=65536", 1);
    EXPECT_FALSE(sph::keepFreedMemoryForReuse());
    unsetenv("GLIBC_TUNABLES");
}
