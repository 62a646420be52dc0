#include "driver/OutOfDomain.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace sph {

OutOfDomain readOutOfDomain(const Dictionary& controlDict) {
    const std::string value = controlDict.getOrDefault<std::string>("outOfDomain", "stop");
    if (value == "stop") return OutOfDomain::Stop;
    if (value == "remove") return OutOfDomain::Remove;
    controlDict.fail("outOfDomain", "expected stop or remove, found '" + value + "'");
}

template <int D>
std::vector<std::uint32_t> fluidOutside(const ParticleSet<D>& fluid, const Vec<D>& domainMin, const Vec<D>& domainMax) {
    std::vector<std::uint32_t> places;
    const auto& x = fluid.position;
    for (std::size_t i = 0; i < x.size(); ++i)
        if (x[i].allFinite() && ((x[i].array() < domainMin.array()).any() || (x[i].array() > domainMax.array()).any()))
            places.push_back(static_cast<std::uint32_t>(i));
    return places;
}

template <int D>
void removeFluid(ParticleSet<D>& fluid, const std::vector<std::uint32_t>& places) {
    std::vector<std::uint32_t> kept;
    kept.reserve(fluid.size() - places.size());
    auto removed = places.begin();
    for (std::uint32_t i = 0; i < fluid.size(); ++i) {
        if (removed != places.end() && *removed == i)
            ++removed;
        else
            kept.push_back(i);
    }
    fluid.keep(kept);
}

void reportRemoved(long step, double t, std::int64_t removed, std::int64_t removedSoFar) {
    fmt::print("Step {}, t = {:.9g}: {} fluid particle{} left the domain and {} removed ({} so far)\n", step, t, removed, removed == 1 ? "" : "s",
               removed == 1 ? "was" : "were", removedSoFar);
}

#define SPHKIT_INSTANTIATE(D)                                                                                 \
    template std::vector<std::uint32_t> fluidOutside<D>(const ParticleSet<D>&, const Vec<D>&, const Vec<D>&); \
    template void removeFluid<D>(ParticleSet<D>&, const std::vector<std::uint32_t>&);
SPHKIT_INSTANTIATE(1)
SPHKIT_INSTANTIATE(2)
SPHKIT_INSTANTIATE(3)
#undef SPHKIT_INSTANTIATE

}  // namespace sph
