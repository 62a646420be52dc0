// Checks a state file's XML header and its appended blocks before VTK's reader sees them:
// VTK trusts the header, and a negative NumberOfPoints or an offset one byte out crashed it
// (SIGSEGV) or asked for more memory than there is (std::bad_alloc).
//
// Accepted: what sphkit writes, and ParaView writes by default: a VTKFile of type
// UnstructuredGrid, little-endian, header_type UInt32 or UInt64, vtkZLibDataCompressor or no
// compressor, every array `format="appended"` in raw `<AppendedData encoding="raw">`. For each
// array: its block lies inside the file, and (strings aside) the block's uncompressed size is
// the one the header implies (NumberOfPoints, NumberOfCells or NumberOfTuples times
// NumberOfComponents times the size of its type). The uncompressed sizes together must fit in
// the available memory.
#pragma once

#include <filesystem>

namespace sph {

// FatalError naming the file, the array and what was found when the file fails a check.
void checkVtuLayout(const std::filesystem::path& file);

}  // namespace sph
