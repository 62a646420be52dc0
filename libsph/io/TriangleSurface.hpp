// A closed triangulated surface read from an STL (ASCII or binary) or Wavefront OBJ file, for
// the generator to fill fluid inside it and to lay walls along it (generation/SurfaceShapes).
// Read by VTK (vtkSTLReader, vtkOBJReader; polygons triangulated), so no VTK type leaves io/:
//   TriangleSurface surface = TriangleSurface::read("constant/geometry/tank.stl", 0.001);  // mm -> m
//   surface.inside(x);                     // ray casting (vtkSelectEnclosedPoints)
//   surface.distance(x, closest);          // unsigned, with the closest point on the surface
// The surface must be closed (every edge shared by two triangles): inside and outside are
// otherwise undefined, and read() says how many edges are open.
#pragma once

#include "core/Vector.hpp"

#include <filesystem>
#include <memory>
#include <vector>

namespace sph {

struct Triangle {
    Vec<3> a, b, c;
    Vec<3> outward;  // unit normal out of the enclosed volume
    double area;
};

class TriangleSurface {
public:
    // Throws FatalError ("surface file '...' ...", for the caller to place) for a missing or
    // unreadable file, an unknown extension, an empty or open surface. `scale` multiplies every
    // coordinate.
    static TriangleSurface read(const std::filesystem::path& file, double scale);
    ~TriangleSurface();
    TriangleSurface(TriangleSurface&&) noexcept;

    const std::vector<Triangle>& triangles() const { return triangles_; }
    const Vec<3>& lower() const { return lower_; }  // bounding box
    const Vec<3>& upper() const { return upper_; }
    bool inside(const Vec<3>& x) const;
    double distance(const Vec<3>& x, Vec<3>& closest) const;

private:
    struct Queries;  // VTK's locators, hidden from the includers
    TriangleSurface();
    std::vector<Triangle> triangles_;
    Vec<3> lower_, upper_;
    std::unique_ptr<Queries> queries_;
};

}  // namespace sph
