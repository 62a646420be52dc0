#include "io/VtuLayout.hpp"

#include "core/FatalError.hpp"
#include "core/MemoryBudget.hpp"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <zlib.h>

namespace sph {

namespace {

struct XmlTag {
    std::string name;  // "/Piece" for a closing tag
    std::map<std::string, std::string> attributes;
    bool selfClosing = false;
};

struct ArrayLayout {
    std::string name, type, section;
    std::uint64_t offset = 0;
    std::optional<std::uint64_t> values;  // elements (strings, for a String array) the header implies; none for connectivity
    std::uint64_t leastValues = 0;        // for connectivity: a point per cell at least
};

class LayoutError {
public:
    explicit LayoutError(const std::filesystem::path& file) : file_(file.string()) {}
    [[noreturn]] void operator()(const std::string& message) const {
        throw FatalError("error: particle file '" + file_ + "': " + message + " (a corrupt state file?)");
    }

private:
    std::string file_;
};

// The tags of the XML text, in order (comments and the <?xml ?> declaration skipped).
std::vector<XmlTag> tagsOf(const std::string& text, const LayoutError& fail) {
    std::vector<XmlTag> tags;
    for (std::size_t at = text.find('<'); at != std::string::npos; at = text.find('<', at)) {
        const std::size_t end = text.find('>', at);
        if (end == std::string::npos) fail("an XML tag is not closed by '>'");
        std::string body = text.substr(at + 1, end - at - 1);
        at = end + 1;
        if (body.starts_with("?") || body.starts_with("!")) continue;
        XmlTag tag;
        if (!body.empty() && body.back() == '/') {
            tag.selfClosing = true;
            body.pop_back();
        }
        std::size_t pos = body.find_first_of(" \t\r\n");
        tag.name = body.substr(0, pos);
        while (pos != std::string::npos && pos < body.size()) {
            const std::size_t nameStart = body.find_first_not_of(" \t\r\n", pos);
            if (nameStart == std::string::npos) break;
            const std::size_t equals = body.find('=', nameStart);
            if (equals == std::string::npos || equals + 1 >= body.size() || body[equals + 1] != '"')
                fail("the attributes of <" + tag.name + "> are not name=\"value\" pairs");
            const std::size_t close = body.find('"', equals + 2);
            if (close == std::string::npos) fail("an attribute of <" + tag.name + "> is not closed by '\"'");
            std::string key = body.substr(nameStart, equals - nameStart);
            while (!key.empty() && (key.back() == ' ' || key.back() == '\t')) key.pop_back();
            tag.attributes[key] = body.substr(equals + 2, close - equals - 2);
            pos = close + 1;
        }
        tags.push_back(std::move(tag));
    }
    return tags;
}

// A whole number >= 0 written in decimal digits only ("-5", "1e3" and "" are not).
std::uint64_t countOf(const XmlTag& tag, const std::string& attribute, const LayoutError& fail, std::optional<std::uint64_t> fallback = {}) {
    const auto found = tag.attributes.find(attribute);
    if (found == tag.attributes.end()) {
        if (fallback) return *fallback;
        fail("<" + tag.name + "> has no " + attribute);
    }
    const std::string& text = found->second;
    const bool digits = !text.empty() && text.size() <= 18 && text.find_first_not_of("0123456789") == std::string::npos;
    if (!digits) fail(attribute + "=\"" + text + "\" in <" + tag.name + "> is not a whole number >= 0");
    return std::stoull(text);
}

std::uint64_t bytesOfType(const std::string& type) {
    static const std::map<std::string, std::uint64_t> sizes{{"Int8", 1},  {"UInt8", 1},  {"Int16", 2},   {"UInt16", 2},  {"Int32", 4}, {"UInt32", 4},
                                                            {"Int64", 8}, {"UInt64", 8}, {"Float32", 4}, {"Float64", 8}, {"String", 1}};
    const auto found = sizes.find(type);
    return found == sizes.end() ? 0 : found->second;
}

struct FileHeader {
    std::string xml;
    std::uint64_t appendedStart = 0;  // the byte after '_'
};

FileHeader readXmlPart(const std::filesystem::path& file, std::uint64_t fileSize, const LayoutError& fail) {
    std::ifstream in(file, std::ios::binary);
    if (!in) fail("cannot be opened for reading");
    // The XML part of any state file is a few kB; 1 MiB without the appended data is not one.
    constexpr std::size_t maxXml = 1u << 20;
    std::string text(static_cast<std::size_t>(std::min<std::uint64_t>(fileSize, maxXml)), '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    text.resize(static_cast<std::size_t>(in.gcount()));
    const std::size_t appended = text.find("<AppendedData");
    if (appended == std::string::npos) {
        if (text.find("format=\"ascii\"") != std::string::npos || text.find("format=\"binary\"") != std::string::npos)
            fail(
                "its arrays are stored inline (format=\"ascii\" or \"binary\"); sphkit reads appended raw data, as it writes "
                "it (in ParaView: Save Data, Data Mode Appended, Encode Appended Data off)");
        fail("has no <AppendedData> section within its first MiB (not a state file written by sphkit or ParaView?)");
    }
    const std::size_t tagEnd = text.find('>', appended);
    // VTK takes the data to start after the first '_'; anything but blanks before it misleads it.
    const std::size_t underscore = tagEnd == std::string::npos ? std::string::npos : text.find_first_not_of(" \t\r\n", tagEnd + 1);
    if (underscore == std::string::npos || text[underscore] != '_')
        fail("its <AppendedData> tag is not followed by '_' (and blanks only) before the data");
    if (text.substr(appended, tagEnd - appended).find("encoding=\"raw\"") == std::string::npos)
        fail("its appended data is not raw (encoding=\"base64\"?); sphkit reads raw appended data, as it writes it");
    return {text.substr(0, tagEnd + 1), underscore + 1};
}

// A string array holds its strings one after another, each ended by a zero byte; VTK's reader
// overran its buffer when the header promised fewer strings than the data holds (found by
// fuzzing). Only field data has string arrays here, a few bytes each: they are inflated and
// their strings counted. `sizes` empty: the data is not compressed.
void checkStrings(const ArrayLayout& array, const std::string& where, const std::string& stored, const std::vector<std::uint64_t>& sizes,
                  std::uint64_t blockSize, std::uint64_t uncompressed, const LayoutError& fail) {
    constexpr std::uint64_t maxStringBytes = 1u << 20;
    if (uncompressed > maxStringBytes) fail(where + " is a string array of " + std::to_string(uncompressed) + " bytes (at most 1 MiB)");
    std::string text;
    if (sizes.empty()) {
        text = stored;
    } else {
        std::size_t at = 0;
        for (std::size_t b = 0; b < sizes.size(); ++b) {
            const std::uint64_t expected = b + 1 < sizes.size() ? blockSize : uncompressed - blockSize * (sizes.size() - 1);
            std::string block(static_cast<std::size_t>(expected), '\0');
            uLongf length = static_cast<uLongf>(expected);
            const int status = ::uncompress(reinterpret_cast<Bytef*>(block.data()), &length, reinterpret_cast<const Bytef*>(stored.data() + at),
                                            static_cast<uLong>(sizes[b]));
            if (status != Z_OK || length != expected)
                fail(where + " has a compressed block that does not inflate to its " + std::to_string(expected) + " bytes");
            text += block;
            at += static_cast<std::size_t>(sizes[b]);
        }
    }
    const auto strings = static_cast<std::uint64_t>(std::count(text.begin(), text.end(), '\0'));
    if (strings != *array.values || (!text.empty() && text.back() != '\0'))
        fail(where + " holds " + std::to_string(strings) + " strings, but NumberOfTuples says " + std::to_string(*array.values));
}

// What the XML part declares: the <VTKFile> tag, the number of pieces, and every data array.
struct XmlLayout {
    const XmlTag* vtkFile = nullptr;
    std::uint64_t pieces = 0;
    std::vector<ArrayLayout> arrays;
};

// A <DataArray> or <Array> in `section` of a piece of `points` points and `cells` cells.
ArrayLayout arrayOf(const XmlTag& tag, const std::string& section, std::uint64_t points, std::uint64_t cells, const LayoutError& fail) {
    ArrayLayout array;
    array.name = tag.attributes.contains("Name") ? tag.attributes.at("Name") : "(unnamed)";
    array.type = tag.attributes.contains("type") ? tag.attributes.at("type") : "";
    array.section = section;
    if (bytesOfType(array.type) == 0) fail("array '" + array.name + "' has type \"" + array.type + "\", not a VTK data type");
    const std::string format = tag.attributes.contains("format") ? tag.attributes.at("format") : "";
    if (format != "appended") fail("array '" + array.name + "' has format=\"" + format + "\"; sphkit reads appended raw data, as it writes it");
    array.offset = countOf(tag, "offset", fail);
    const std::uint64_t components = countOf(tag, "NumberOfComponents", fail, 1);
    if (components == 0 || components > 1024)
        fail("array '" + array.name + "' has NumberOfComponents=\"" + std::to_string(components) + "\" (valid: 1 to 1024)");
    std::optional<std::uint64_t> tuples;
    if (section == "FieldData") tuples = countOf(tag, "NumberOfTuples", fail);
    if (section == "PointData" || section == "Points") tuples = points;
    if (section == "CellData" || (section == "Cells" && array.name != "connectivity")) tuples = cells;
    if (section == "Cells" && array.name == "connectivity") array.leastValues = cells;
    if (tuples) {
        if (*tuples > (std::uint64_t{1} << 40)) fail("array '" + array.name + "' claims " + std::to_string(*tuples) + " tuples");
        array.values = *tuples * components;
    }
    return array;
}

XmlLayout layoutOf(const std::vector<XmlTag>& tags, const LayoutError& fail) {
    XmlLayout layout;
    std::uint64_t points = 0, cells = 0;
    std::string section;
    // VTK's reader dereferences what it makes of an element it does not know (found by fuzzing:
    // <DataArrayy> in FieldData crashed it): only the elements of an unstructured grid pass.
    static const std::vector<std::string> elements{"VTKFile", "UnstructuredGrid", "FieldData", "Piece",        "PointData",      "CellData", "Points",
                                                   "Cells",   "DataArray",        "Array",     "AppendedData", "InformationKey", "Value"};
    for (const XmlTag& tag : tags) {
        const std::string element = tag.name.starts_with("/") ? tag.name.substr(1) : tag.name;
        if (std::find(elements.begin(), elements.end(), element) == elements.end())
            fail("has the XML element <" + tag.name + ">, which a VTK unstructured grid does not have");
        if (tag.name == "VTKFile") {
            layout.vtkFile = &tag;
        } else if (tag.name == "Piece") {
            if (++layout.pieces > 1) fail("has more than one <Piece>; sphkit writes one");
            points = countOf(tag, "NumberOfPoints", fail);
            cells = countOf(tag, "NumberOfCells", fail);
        } else if (tag.name == "FieldData" || tag.name == "PointData" || tag.name == "CellData" || tag.name == "Points" || tag.name == "Cells") {
            if (!tag.selfClosing) section = tag.name;
        } else if (tag.name.starts_with("/") && tag.name != "/DataArray" && tag.name != "/Array") {
            section.clear();
        } else if (tag.name == "DataArray" || tag.name == "Array") {
            layout.arrays.push_back(arrayOf(tag, section, points, cells, fail));
        }
    }
    return layout;
}

// The appended data: header words and bytes at offsets into it.
class AppendedData {
public:
    AppendedData(const std::filesystem::path& file, std::uint64_t start, std::uint64_t fileSize, std::uint64_t word)
        : in_(file, std::ios::binary), start_(start), bytes_(fileSize - start), word_(word) {}

    std::uint64_t bytes() const { return bytes_; }
    std::uint64_t word() const { return word_; }

    // Reads `count` header words at `at` (false if past the end).
    bool readWords(std::uint64_t at, std::uint64_t count, std::vector<std::uint64_t>& words) {
        if (at > bytes_ || count > (bytes_ - at) / word_) return false;
        words.assign(static_cast<std::size_t>(count), 0);
        in_.seekg(static_cast<std::streamoff>(start_ + at));
        for (std::uint64_t& w : words) {
            std::uint64_t value = 0;
            in_.read(reinterpret_cast<char*>(&value), static_cast<std::streamsize>(word_));
            w = value;
        }
        return static_cast<bool>(in_);
    }

    // Reads `count` bytes at `at` (inside the file: checked before).
    std::string readBytes(std::uint64_t at, std::uint64_t count) {
        std::string data(static_cast<std::size_t>(count), '\0');
        in_.seekg(static_cast<std::streamoff>(start_ + at));
        in_.read(data.data(), static_cast<std::streamsize>(count));
        return data;
    }

private:
    std::ifstream in_;
    std::uint64_t start_, bytes_, word_;
};

// Checks that an array's data lies in the file and holds what its header implies; returns its
// uncompressed size in bytes.
std::uint64_t checkArrayData(const ArrayLayout& array, AppendedData& data, bool compressed, const LayoutError& fail) {
    const std::string where = "array '" + array.name + "' (offset " + std::to_string(array.offset) + ")";
    const std::uint64_t word = data.word(), appendedBytes = data.bytes();
    std::vector<std::uint64_t> words, sizes;
    std::uint64_t dataStart = 0, stored = 0, uncompressed = 0, blockSize = 0;
    if (!compressed) {
        if (!data.readWords(array.offset, 1, words)) fail(where + " starts past the end of the file");
        dataStart = array.offset + word;
        stored = uncompressed = words[0];
    } else {
        if (!data.readWords(array.offset, 3, words)) fail(where + " starts past the end of the file");
        const std::uint64_t blocks = words[0], lastBlock = words[2];
        blockSize = words[1];
        if (blocks > 0 && (blockSize == 0 || lastBlock > blockSize))
            fail(where + " has a compression header of " + std::to_string(blocks) + " blocks of " + std::to_string(blockSize) + " bytes, the last " +
                 std::to_string(lastBlock) + ": not a valid one");
        if (!data.readWords(array.offset + 3 * word, blocks, sizes))
            fail(where + " claims " + std::to_string(blocks) + " compressed blocks, more than the file holds");
        dataStart = array.offset + (3 + blocks) * word;
        for (std::uint64_t size : sizes) {
            if (size > appendedBytes) fail(where + " has a compressed block of " + std::to_string(size) + " bytes, more than the file holds");
            stored += size;
        }
        uncompressed = blocks == 0 ? 0 : (blocks - 1) * blockSize + (lastBlock == 0 ? blockSize : lastBlock);
        // zlib compresses by at most about 1032:1 (deflate's longest match per 2 bits).
        if (blocks > 0 && (blockSize > (std::uint64_t{1} << 40) || uncompressed / 1032 > stored + 64 * blocks))
            fail(where + " claims " + std::to_string(uncompressed) + " bytes from " + std::to_string(stored) +
                 " compressed ones, more than zlib can compress");
    }
    if (dataStart > appendedBytes || stored > appendedBytes - dataStart)
        fail(where + " holds " + std::to_string(stored) + " bytes that run past the end of the file");
    const std::uint64_t elementBytes = bytesOfType(array.type);
    if (array.values && array.type != "String" && uncompressed != *array.values * elementBytes)
        fail(where + " holds " + std::to_string(uncompressed) + " bytes, but the header implies " + std::to_string(*array.values) + " values of " +
             std::to_string(elementBytes) + " bytes (" + array.section + ")");
    // Found by fuzzing: a connectivity offset one byte out read as zero blocks, which VTK then
    // read through a null buffer.
    if (uncompressed % elementBytes != 0 || uncompressed / elementBytes < array.leastValues)
        fail(where + " holds " + std::to_string(uncompressed) + " bytes, not a whole number of at least " + std::to_string(array.leastValues) +
             " values of " + std::to_string(elementBytes) + " bytes (" + array.section + ")");
    if (array.type == "String" && array.values) checkStrings(array, where, data.readBytes(dataStart, stored), sizes, blockSize, uncompressed, fail);
    return uncompressed;
}

}  // namespace

void checkVtuLayout(const std::filesystem::path& file) {
    const LayoutError fail(file);
    std::error_code ec;
    const std::uint64_t fileSize = std::filesystem::file_size(file, ec);
    if (ec) fail("cannot be read: " + ec.message());
    const FileHeader header = readXmlPart(file, fileSize, fail);
    const std::vector<XmlTag> tags = tagsOf(header.xml, fail);
    const XmlLayout layout = layoutOf(tags, fail);
    const XmlTag* vtkFile = layout.vtkFile;
    if (!vtkFile || !vtkFile->attributes.contains("type") || vtkFile->attributes.at("type") != "UnstructuredGrid")
        fail("is not a VTK XML UnstructuredGrid (<VTKFile type=\"UnstructuredGrid\"> not found)");
    if (layout.pieces == 0) fail("has no <Piece>");
    const auto attribute = [&](const std::string& name) {
        const auto found = vtkFile->attributes.find(name);
        return found == vtkFile->attributes.end() ? std::string() : found->second;
    };
    if (attribute("byte_order") != "LittleEndian") fail("byte_order=\"" + attribute("byte_order") + "\" (valid: LittleEndian)");
    const std::string headerType = attribute("header_type").empty() ? "UInt32" : attribute("header_type");
    if (headerType != "UInt32" && headerType != "UInt64") fail("header_type=\"" + headerType + "\" (valid: UInt32, UInt64)");
    const std::string compressor = attribute("compressor");
    if (!compressor.empty() && compressor != "vtkZLibDataCompressor")
        fail("compressor=\"" + compressor + "\" (valid: vtkZLibDataCompressor, or none)");

    AppendedData data(file, header.appendedStart, fileSize, headerType == "UInt64" ? 8 : 4);
    double uncompressedTotal = 0.0;
    for (const ArrayLayout& array : layout.arrays) uncompressedTotal += static_cast<double>(checkArrayData(array, data, !compressor.empty(), fail));
    requireMemory(2.0 * uncompressedTotal, "reading particle file '" + file.string() + "'");
}

}  // namespace sph
