#include "io/PvdCollection.hpp"

#include "io/AtomicFile.hpp"

#include <fmt/format.h>

namespace sph {

void PvdCollection::add(double time, const std::vector<std::string>& files) {
    for (std::size_t part = 0; part < files.size(); ++part) dataSets_.push_back({time, static_cast<int>(part), files[part]});
    std::string xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n";
    for (const DataSet& d : dataSets_)
        xml += fmt::format("    <DataSet timestep=\"{:.12g}\" group=\"\" part=\"{}\" file=\"{}\"/>\n", d.time, d.part, d.file);
    xml += "  </Collection>\n</VTKFile>\n";
    writeTextAtomically(file_, xml);
}

}  // namespace sph
