#include "io/ParticleCsv.hpp"

#include "io/AtomicFile.hpp"

#include <fmt/format.h>

namespace sph {

template <int D>
void writeParticleCsv(const std::filesystem::path& file, const ParticleSet<D>& particles) {
    constexpr const char* axes = "xyz";
    std::string text = "id";
    for (int d = 0; d < D; ++d) text += fmt::format(",{}", axes[d]);
    for (const auto& [name, field] : particles.scalars())
        if (field.written) text += "," + name;
    for (const auto& [name, field] : particles.vectors())
        if (field.written)
            for (int d = 0; d < D; ++d) text += fmt::format(",{}_{}", name, axes[d]);
    for (const auto& [name, field] : particles.integers())
        if (field.written) text += "," + name;
    text += "\n";
    for (std::size_t i = 0; i < particles.size(); ++i) {
        text += std::to_string(particles.globalId[i]);
        for (int d = 0; d < D; ++d) text += fmt::format(",{:.12g}", particles.position[i][d]);
        for (const auto& [name, field] : particles.scalars())
            if (field.written) text += fmt::format(",{:.12g}", field.values[i]);
        for (const auto& [name, field] : particles.vectors())
            if (field.written)
                for (int d = 0; d < D; ++d) text += fmt::format(",{:.12g}", field.values[i][d]);
        for (const auto& [name, field] : particles.integers())
            if (field.written) text += fmt::format(",{}", field.values[i]);
        text += "\n";
    }
    writeTextAtomically(file, text);
}

template void writeParticleCsv<1>(const std::filesystem::path&, const ParticleSet<1>&);
template void writeParticleCsv<2>(const std::filesystem::path&, const ParticleSet<2>&);
template void writeParticleCsv<3>(const std::filesystem::path&, const ParticleSet<3>&);

}  // namespace sph
