// Closed shapes written as files for the surface tests. A unit cube [0, 1]^3 as a Wavefront OBJ file of six quads, written for the surface tests. Its
// faces are listed clockwise seen from outside (normals inward), which the reader must turn
// outward; `leaveOut` drops the top face to make an open surface.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

inline std::filesystem::path writeCubeObj(const std::string& name, bool leaveOut = false) {
    const std::filesystem::path directory = std::filesystem::path(SPHKIT_TEST_WORK_DIR) / "surfaces";
    std::filesystem::create_directories(directory);
    const std::filesystem::path file = directory / name;
    std::ofstream out(file);
    out << "# unit cube\n";
    for (int k = 0; k < 8; ++k) out << "v " << (k & 1) << ' ' << ((k >> 1) & 1) << ' ' << ((k >> 2) & 1) << '\n';
    // Vertex k is (k & 1, k >> 1 & 1, k >> 2 & 1), 1-based in OBJ.
    out << "f 2 4 3 1\n"                  // z = 0
           "f 5 6 2 1\n"                  // y = 0
           "f 3 7 5 1\n"                  // x = 0
           "f 6 8 4 2\n"                  // x = 1
           "f 4 8 7 3\n";                 // y = 1
    if (!leaveOut) out << "f 7 8 6 5\n";  // z = 1
    return file;
}

// A closed polyline in the plane z = 0 as an OBJ of `l` lines (its first point repeated at its
// end unless `open`), for the 2D surface tests.
template <class Points>
std::filesystem::path writeCurveObj(const std::string& name, const Points& points, bool open = false) {
    const std::filesystem::path directory = std::filesystem::path(SPHKIT_TEST_WORK_DIR) / "surfaces";
    std::filesystem::create_directories(directory);
    const std::filesystem::path file = directory / name;
    std::ofstream out(file);
    out.precision(17);
    for (const auto& x : points) out << "v " << x[0] << ' ' << x[1] << " 0\n";
    out << 'l';
    for (std::size_t k = 1; k <= points.size(); ++k) out << ' ' << k;
    out << (open ? "\n" : " 1\n");
    return file;
}
