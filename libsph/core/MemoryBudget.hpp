// A request that depends on input (a particle count, a number of layers or sample points) is
// checked against the machine's memory before anything is allocated, so that a typing slip
// such as `spacing 1e-5` is refused with its size rather than ending in std::bad_alloc.
#pragma once

#include <string>

namespace sph {

// Bytes this process may still allocate: MemAvailable from /proc/meminfo (physical memory
// where that is not readable).
double availableMemoryBytes();

// FatalError "<what> would need <n> GiB of memory; this machine has <m> GiB available" when
// `bytes` exceeds the available memory. `what` names the file and keyword that asked for it.
void requireMemory(double bytes, const std::string& what);

}  // namespace sph
