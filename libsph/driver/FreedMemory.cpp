#include "driver/FreedMemory.hpp"

#include <malloc.h>

#include <cstdlib>
#include <string_view>

namespace sph {

bool keepFreedMemoryForReuse() {
    const char* tunables = std::getenv("GLIBC_TUNABLES");
    if ((tunables && std::string_view(tunables).find("glibc.malloc.") != std::string_view::npos) || std::getenv("MALLOC_MMAP_THRESHOLD_") ||
        std::getenv("MALLOC_TRIM_THRESHOLD_"))
        return false;
    constexpr int largestMmapThreshold = 32 << 20;  // glibc refuses more on 64-bit
    constexpr int keptWhenFreed = 1 << 30;          // far above what a run frees at once
    return mallopt(M_MMAP_THRESHOLD, largestMmapThreshold) == 1 && mallopt(M_TRIM_THRESHOLD, keptWhenFreed) == 1;
}

}  // namespace sph
