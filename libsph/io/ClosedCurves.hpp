// Closed curves in the plane read from a file, for the 2D generator to fill fluid inside them
// and to lay walls along them (generation/SurfaceShapes): an OBJ of polylines (`v x y z` and
// `l i j k ...`), or the cross-section at z = `slice` of a closed STL or OBJ surface (a 3D tank
// model cut through, as the 2D case's plane). Read by VTK (vtkOBJReader, vtkSTLReader,
// vtkCutter, vtkStripper), so no VTK type leaves io/:
//   ClosedCurves curves = ClosedCurves::read("constant/geometry/tank.obj", 0.001, 0.0);  // mm -> m
//   curves.inside(x);                    // even-odd over every curve
//   curves.distance(x, closest);         // unsigned, with the closest point on a curve
// Each curve must close (its polylines join end to end into loops): inside and outside are
// otherwise undefined, and read() says how many ends are left open.
#pragma once

#include "core/Vector.hpp"

#include <filesystem>
#include <vector>

namespace sph {

class ClosedCurves {
public:
    // Throws FatalError ("surface file '...' ...", for the caller to place) for a missing or
    // unreadable file, an unknown extension, no curve (a surface the slice misses), an open
    // curve. `scale` multiplies every coordinate, `slice` is the cut's z before scaling.
    static ClosedCurves read(const std::filesystem::path& file, double scale, double slice);

    // Each curve's vertices in order, counter-clockwise, its first vertex not repeated at its end.
    const std::vector<std::vector<Vec<2>>>& loops() const { return loops_; }
    const Vec<2>& lower() const { return lower_; }  // bounding box
    const Vec<2>& upper() const { return upper_; }
    bool inside(const Vec<2>& x) const;
    double distance(const Vec<2>& x, Vec<2>& closest) const;

private:
    std::vector<std::vector<Vec<2>>> loops_;
    Vec<2> lower_, upper_;
};

}  // namespace sph
