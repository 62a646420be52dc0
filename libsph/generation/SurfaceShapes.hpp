// Fluid regions and wall patches bounded by closed surfaces (3D) or curves (2D) from a file,
// its path relative to the case, `scale` (default 1) multiplying its coordinates:
//   fluid      { water { type surface; file "constant/geometry/water.stl"; scale 0.001; } }
//   boundaries { tank  { type surface; file "constant/geometry/tank.obj"; layers 3; fluidInside yes; } }
// 3D: a closed STL or OBJ surface (io/TriangleSurface). 2D: the closed polylines of an OBJ
// (`l` lines), or a closed STL or OBJ surface cut by the plane z = `slice` (default 0), so a 3D
// model gives its cross-section (io/ClosedCurves); several loops nest by the even-odd rule.
// Fluid: the domain's lattice points inside the surface (as other shapes keep theirs).
// Walls of several layers (dummy particles, dynamic boundary): the domain's lattice points on
// the wall's side of the surface less than `layers` dx from it, in layer floor(distance / dx),
// the normal towards the closest point of the surface (into the fluid; diagonal past edges and
// corners, as boxWalls'). The wall surface then lies halfway between fluid and wall particles
// only where it falls halfway between lattice planes; firstLayerOffset is refused.
// Walls of one layer (wall-force models, the deficiency correction), moved firstLayerOffset dx
// behind the surface (1/2 by default, 0 for those models), each particle with the surface's
// normal into the fluid and the length (2D) or area (3D) it stands for:
// - 2D: each curve resampled at about dx, its corners (vertices turning by more than 20
//   degrees) kept and each stretch between them divided into equal lengths, then laid as a
//   polygon's wall (a particle on every vertex, the bisector normal).
// - 3D: the surface sampled triangle by triangle. A triangle facing an axis (a floor, a wall
//   of a box) takes the points where the domain's lattice columns along that axis pierce it,
//   dx^2 each: the lattice's own, as boxWalls' faces (a point on an edge two triangles share
//   goes to one of them). Any other triangle is halved across its longest edge until no edge
//   exceeds 2 dx, a particle at each piece's centroid standing for its area (dx^2 / 2 to dx^2
//   for right-angled pieces), so the area vectors add up to the surface's, thin CAD triangles
//   included.
// fluidInside yes: a tank (walls outside the surface); no: a solid body that fluid regions leave out.
#pragma once

#include "generation/FluidRegions.hpp"
#include "generation/WallPatches.hpp"

#include <filesystem>

namespace sph {

template <int D>
std::vector<Vec<D>> fillSurface(const Dictionary& region, double dx, const GenerationDomain<D>& domain);

template <int D>
WallPatchParticles<D> surfaceWalls(const Dictionary& patch, double dx, const WallLayout& layout, const std::filesystem::path& caseDirectory,
                                   const Vec<D>& domainMin, const Vec<D>& domainMax);

}  // namespace sph
