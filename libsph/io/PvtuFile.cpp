#include "io/PvtuFile.hpp"

#include "core/FatalError.hpp"
#include "io/AtomicFile.hpp"

#include <fmt/format.h>

#include <fstream>
#include <regex>
#include <sstream>

namespace sph {

template <int D>
std::vector<PointArray> writtenPointArrays(const ParticleSet<D>& particles) {
    std::vector<PointArray> arrays{{"id", "Int64", 1}};
    for (const auto& [name, field] : particles.scalars())
        if (field.written) arrays.push_back({name, "Float64", 1});
    for (const auto& [name, field] : particles.vectors())
        if (field.written) arrays.push_back({name, "Float64", 3});
    for (const auto& [name, field] : particles.integers())
        if (field.written) arrays.push_back({name, "Int32", 1});
    return arrays;
}

void writePvtu(const std::filesystem::path& file, const std::vector<PointArray>& arrays, const std::vector<std::string>& pieces) {
    std::string text =
        "<?xml version=\"1.0\"?>\n"
        "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
        "  <PUnstructuredGrid GhostLevel=\"0\">\n    <PPointData>\n";
    for (const PointArray& array : arrays)
        text += fmt::format("      <PDataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\"/>\n", array.type, array.name, array.components);
    text +=
        "    </PPointData>\n    <PPoints>\n      <PDataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"/>\n"
        "    </PPoints>\n";
    for (const std::string& piece : pieces) text += fmt::format("    <Piece Source=\"{}\"/>\n", piece);
    text += "  </PUnstructuredGrid>\n</VTKFile>\n";
    writeTextAtomically(file, text);
}

std::vector<std::filesystem::path> readPvtuPieces(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) throw FatalError("error: cannot read the piece index '" + file.string() + "'");
    std::stringstream text;
    text << in.rdbuf();
    const std::string content = text.str();
    std::vector<std::filesystem::path> pieces;
    static const std::regex piece(R"re(<Piece\s+Source="([^"]+)")re");
    for (auto match = std::sregex_iterator(content.begin(), content.end(), piece); match != std::sregex_iterator(); ++match) {
        const std::filesystem::path path = file.parent_path() / (*match)[1].str();
        if (!std::filesystem::is_regular_file(path))
            throw FatalError("error: piece index '" + file.string() + "' names the piece '" + (*match)[1].str() + "', which is not there");
        pieces.push_back(path);
    }
    if (pieces.empty()) throw FatalError("error: piece index '" + file.string() + "' names no piece (<Piece Source=\"...\"/>)");
    return pieces;
}

template std::vector<PointArray> writtenPointArrays(const ParticleSet<1>&);
template std::vector<PointArray> writtenPointArrays(const ParticleSet<2>&);
template std::vector<PointArray> writtenPointArrays(const ParticleSet<3>&);

}  // namespace sph
