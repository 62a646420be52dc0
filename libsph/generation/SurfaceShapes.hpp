// Fluid regions and wall patches bounded by a closed surface from a file (STL or OBJ; 3D),
// its path relative to the case, `scale` (default 1) multiplying its coordinates:
//   fluid      { water { type surface; file "constant/geometry/water.stl"; scale 0.001; } }
//   boundaries { tank  { type surface; file "constant/geometry/tank.obj"; layers 3; fluidInside yes; } }
// Fluid: the domain's lattice points inside the surface (as other shapes keep theirs).
// Walls of several layers (dummy particles, dynamic boundary): the domain's lattice points on
// the wall's side of the surface less than `layers` dx from it, in layer floor(distance / dx),
// the normal towards the closest point of the surface (into the fluid; diagonal past edges and
// corners, as boxWalls'). The wall surface then lies halfway between fluid and wall particles
// only where it falls halfway between lattice planes; firstLayerOffset is refused.
// Walls of one layer (wall-force models, the deficiency correction): the surface sampled
// triangle by triangle, moved firstLayerOffset dx behind it (1/2 by default, 0 for those
// models), each particle with the triangle's normal into the fluid and the area it stands for.
// A triangle facing an axis (a floor, a wall of a box) takes the points where the domain's
// lattice columns along that axis pierce it, dx^2 each: the lattice's own, as boxWalls' faces
// (a point on an edge two triangles share goes to one of them). Any other triangle is halved
// across its longest edge until no edge exceeds 2 dx, a particle at each piece's centroid
// standing for its area (dx^2 / 2 to dx^2 for right-angled pieces), so the area vectors add
// up to the surface's, thin CAD triangles included.
// fluidInside yes: a tank (walls outside the surface); no: a solid body that fluid regions leave out.
#pragma once

#include "generation/FluidRegions.hpp"
#include "generation/WallPatches.hpp"

#include <filesystem>

namespace sph {

std::vector<Vec<3>> fillSurface(const Dictionary& region, double dx, const std::filesystem::path& caseDirectory, const Vec<3>& domainMin,
                                const Vec<3>& domainMax);

WallPatchParticles<3> surfaceWalls(const Dictionary& patch, double dx, const WallLayout& layout, const std::filesystem::path& caseDirectory,
                                   const Vec<3>& domainMin, const Vec<3>& domainMax);

}  // namespace sph
