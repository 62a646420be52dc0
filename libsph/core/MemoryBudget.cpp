#include "core/MemoryBudget.hpp"

#include "core/FatalError.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <unistd.h>

namespace sph {

double availableMemoryBytes() {
    std::ifstream meminfo("/proc/meminfo");
    for (std::string line; std::getline(meminfo, line);) {
        if (!line.starts_with("MemAvailable:")) continue;
        std::istringstream fields(line.substr(13));
        double kibibytes = 0.0;
        if (fields >> kibibytes) return kibibytes * 1024.0;
    }
    return static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * static_cast<double>(::sysconf(_SC_PAGE_SIZE));
}

void requireMemory(double bytes, const std::string& what) {
    const double available = availableMemoryBytes();
    if (!(bytes <= available))
        throw FatalError(fmt::format("error: {} would need {:.3g} GiB of memory; this machine has {:.3g} GiB available", what, bytes / 1073741824.0,
                                     available / 1073741824.0));
}

}  // namespace sph
