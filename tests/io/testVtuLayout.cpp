// State files edited by hand or damaged: every header edit and every cut is a FatalError
// naming the file, before VTK's reader (which crashed on some) sees the file.
#include "core/FatalError.hpp"
#include "io/ParticleFile.hpp"
#include "io/VtuLayout.hpp"
#include "support/CaseFixture.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>

namespace {

// A small state, as the solver writes it.
std::filesystem::path writeState(const std::filesystem::path& dir) {
    sph::ParticleSet<2> set("fluid");
    set.resize(6);
    auto& rho = set.add(sph::fields::density, 1000.0);
    set.add(sph::fields::velocity, sph::Vec<2>::Zero());
    for (std::size_t i = 0; i < set.size(); ++i) {
        set.position[i] = {0.01 * static_cast<double>(i), 0.5};
        set.globalId[i] = static_cast<std::int64_t>(i);
        rho[i] += static_cast<double>(i);
    }
    sph::StateHeader header;
    header.dimension = 2;
    header.spacing = 0.01;
    header.domainMin = {0, 0};
    header.domainMax = {1, 1};
    header.integrator = "symplectic";
    sph::writeParticleFile(dir / "fluid.vtu", set, header);
    return dir / "fluid.vtu";
}

std::string bytesOf(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void writeBytes(const std::filesystem::path& file, const std::string& bytes) { std::ofstream(file, std::ios::binary) << bytes; }

// The FatalError message of reading `file` ("" if it reads).
std::string readError(const std::filesystem::path& file) {
    try {
        sph::StateHeader header;
        sph::readParticleFile<2>(file, "fluid", header);
    } catch (const sph::FatalError& e) {
        return e.what();
    }
    return "";
}

// Applies `edit` (a regex and its replacement, first match) to the XML part of a fresh state.
std::string errorAfterEdit(const std::string& pattern, const std::string& replacement) {
    const auto file = writeState(sph::test::freshDirectory());
    std::string bytes = bytesOf(file);
    const std::size_t appended = bytes.find('_', bytes.find("<AppendedData"));
    std::string xml = bytes.substr(0, appended);
    EXPECT_TRUE(std::regex_search(xml, std::regex(pattern))) << pattern;
    xml = std::regex_replace(xml, std::regex(pattern), replacement, std::regex_constants::format_first_only);
    writeBytes(file, xml + bytes.substr(appended));
    return readError(file);
}

}  // namespace

TEST(VtuLayout, TheFileAsWrittenPasses) {
    const auto file = writeState(sph::test::freshDirectory());
    EXPECT_NO_THROW(sph::checkVtuLayout(file));
    EXPECT_EQ(readError(file), "");
}

TEST(VtuLayout, HeaderEditsAreClearErrors) {
    // Each of these crashed VTK's reader (SIGSEGV) or ended in std::bad_alloc on c09449c.
    EXPECT_NE(errorAfterEdit(R"(NumberOfPoints="6")", R"(NumberOfPoints="-5")").find(R"(NumberOfPoints="-5" in <Piece> is not a whole number >= 0)"),
              std::string::npos);
    EXPECT_NE(errorAfterEdit(R"(NumberOfPoints="6")", R"(NumberOfPoints="60000000000")").find("but the header implies 60000000000 values"),
              std::string::npos);
    EXPECT_NE(errorAfterEdit(R"(NumberOfCells="6")", R"(NumberOfCells="7")").find("array 'connectivity'"), std::string::npos);
    // The Points array's offset one byte past its place (the number after `offset="` plus 1).
    const std::string bytes = bytesOf(writeState(sph::test::freshDirectory()));
    const std::size_t at = bytes.find("offset=\"", bytes.find("Name=\"Points\"")) + 8;
    const std::string offset = bytes.substr(at, bytes.find('"', at) - at);
    const std::string shifted = errorAfterEdit("Name=\"Points\"([^>]*)offset=\"" + offset + "\"",
                                               "Name=\"Points\"$1offset=\"" + std::to_string(std::stoi(offset) + 1) + "\"");
    EXPECT_NE(shifted.find("array 'Points' (offset " + std::to_string(std::stoi(offset) + 1) + ")"), std::string::npos) << shifted;
    EXPECT_NE(errorAfterEdit(R"((Name="density"[^/]*offset=")([0-9]+))", "$1$2 1").find("offset=\""), std::string::npos);
    EXPECT_NE(errorAfterEdit(R"(NumberOfTuples="2")", R"(NumberOfTuples="3")").find("array 'domainMin'"), std::string::npos);
    EXPECT_NE(errorAfterEdit(R"(format="appended")", R"(format="ascii")").find(R"(has format="ascii"; sphkit reads appended raw data)"),
              std::string::npos);
    EXPECT_NE(errorAfterEdit(R"(type="Float64")", R"(type="Float65")").find(R"(has type "Float65", not a VTK data type)"), std::string::npos);
    EXPECT_NE(errorAfterEdit(R"(NumberOfComponents="3")", R"(NumberOfComponents="0")").find("valid: 1 to 1024"), std::string::npos);
    EXPECT_NE(errorAfterEdit("LittleEndian", "BigEndian").find(R"(byte_order="BigEndian" (valid: LittleEndian))"), std::string::npos);
    EXPECT_NE(errorAfterEdit(R"(header_type="UInt\d+")", R"(header_type="UInt16")").find("valid: UInt32, UInt64"), std::string::npos);
    EXPECT_NE(errorAfterEdit("vtkZLibDataCompressor", "vtkLZ4DataCompressor").find("valid: vtkZLibDataCompressor, or none"), std::string::npos);
    EXPECT_NE(errorAfterEdit(R"(type="UnstructuredGrid")", R"(type="PolyData")").find("is not a VTK XML UnstructuredGrid"), std::string::npos);
    EXPECT_NE(errorAfterEdit(R"(encoding="raw")", R"(encoding="base64")").find("appended data is not raw"), std::string::npos);
    // Found by fuzzStateFile: an element VTK does not know, in FieldData, crashed its reader.
    EXPECT_NE(errorAfterEdit("<DataArray type=\"Float64\" Name=\"step\"", "<DataArrayy type=\"Float64\" Name=\"step\"")
                  .find("has the XML element <DataArrayy>, which a VTK unstructured grid does not have"),
              std::string::npos);
}

TEST(VtuLayout, EveryCutOfTheFileIsAClearError) {
    // A state cut at any byte (a copy from a full disk): an error naming the file, never a crash
    // and never fewer particles.
    const auto dir = sph::test::freshDirectory();
    const std::string whole = bytesOf(writeState(dir));
    const auto file = dir / "cut.vtu";
    int read = 0;
    for (std::size_t length = 0; length + 30 < whole.size(); length += 7) {
        writeBytes(file, whole.substr(0, length));
        const std::string error = readError(file);
        EXPECT_NE(error.find("error: particle file '" + file.string() + "'"), std::string::npos) << "cut at " << length << ": " << error;
        ++read;
    }
    EXPECT_GT(read, 100);
}

TEST(VtuLayout, EveryByteChangedIsAnErrorOrTheSameState) {
    // Any one byte of the file changed (bit rot, a slip in an editor): a FatalError, or a file
    // that still reads; never a crash, never an exception of another kind.
    const auto dir = sph::test::freshDirectory();
    const std::string whole = bytesOf(writeState(dir));
    const auto file = dir / "changed.vtu";
    int errors = 0;
    for (std::size_t at = 0; at < whole.size(); ++at) {
        std::string bytes = whole;
        bytes[at] = static_cast<char>(bytes[at] ^ 0x5a);
        writeBytes(file, bytes);
        if (!readError(file).empty()) ++errors;
    }
    EXPECT_GT(errors, static_cast<int>(whole.size() / 4));
}
