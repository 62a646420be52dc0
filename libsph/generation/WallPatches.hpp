// Wall patches of system/generateParticlesDict: surfaces of wall particles, each particle with
// a unit normal pointing into the fluid, its spacing along the wall, and its layer (0 nearest
// the fluid). Layer k lies (k + firstLayerOffset) dx behind the wall surface; the offset 1/2
// puts the surface halfway between fluid and wall particles (Adami et al. 2012), 0 on the first
// layer. A patch without `layers` takes the layout its wall model needs, one without
// `firstLayerOffset` the offset (driver/WallLayoutFromModel; 1/2 for a patch with no model).
//   boundaries
//   {
//       tank     { type boxWalls; min (0 0); max (1.6 0.8); layers 3; open (yMax); }  // 1D-3D
//       block    { type box; min (0.9 0); max (1.02 0.12); layers 3; }                 // 1D-3D, an obstacle
//       ramp     { type polyline; points ((0 0) (1 0.5)); layers 3; side left; }     // 2D
//       tank     { type polygon; points ((0 0) (4 0) (4 2) (0 2)); layers 1; firstLayerOffset 0; } // 2D, closed
//       cylinder { type circle; centre (0.5 0.5); radius 0.1; layers 3; fluidInside no; }  // 2D
//       bowl     { type ellipse; centre (0 0); semiAxes (2 1); layers 3; fluidInside yes; } // 2D
//   }
// box and boxWalls take any extent: along an axis that is not a whole number of spacings the
// last spacing inside the box is adjusted (FluidRegions.hpp), and the lattice continues
// outwards from the nearer end, so the layers lie at the same distances from every face (the
// face particles next to the adjusted spacing stand for the length of wall they cover).
// boxWalls fills the shell around the box with the lattice continued outwards, corners
// included; the normal points to the nearest point of the box (diagonal in corners); a
// firstLayerOffset other than 1/2 moves every particle by (1/2 - offset) dx towards the box
// along each axis it lies outside, so with offset 0 the first layer's edge and corner
// particles sit on the box's edges and corners. The face particles of a layer tile its faces,
// so edge and corner particles stand for no area (a polygon vertex stands for half of each
// adjacent side: its area vector is the sum of the two half-sides' area vectors).
// box is a solid obstacle: its lattice `layers` deep inside each face, normals out of the
// nearest face (diagonal at edges and corners); fluid regions leave out its inside, as they
// do the inside of a circle or ellipse with fluidInside no.
// polyline's and polygon's normal is on the `side` (left or right) of the direction of travel;
// a polygon (closed) has a particle on each vertex, its normal along the bisector, so a
// counter-clockwise polygon with side left is a tank whose particle 0 sits on the first point.
// At their corners, layers behind the wall fill the gap where the wall's side is convex (the
// faces' offset lines extended to their mitre up to a right angle, which gives a right-angled
// corner its lattice block; an arc of the layer's depth beyond) and keep each particle once
// where it is concave (it belongs to the nearer face); layers on the surface are as they were.
#pragma once

#include "core/Vector.hpp"
#include "generation/FluidRegions.hpp"
#include "io/Dictionary.hpp"

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace sph {

template <int D>
struct WallPatchParticles {
    std::vector<Vec<D>> positions;
    std::vector<Vec<D>> normals;
    std::vector<double> spacings;
    std::vector<int> layers;
    std::vector<double> areas;  // the length (2D) or area (3D) of wall each particle stands for
    // For an obstacle (a closed curve with the fluid outside): true inside it, where no fluid goes.
    std::function<bool(const Vec<D>&)> solid;
    // A solid whose layers from opposite faces meet inside it, at least as thick as its layers:
    // the fluid at any face finds them all behind it, though no particle lies that deep from
    // its own face (the wall field `layer` counts from the nearest face).
    bool filledThrough = false;
    std::vector<std::string> notes;  // adjusted spacings, for the user to read

    void add(const Vec<D>& x, const Vec<D>& n, double spacing, int layer, double area) {
        positions.push_back(x);
        normals.push_back(n);
        spacings.push_back(spacing);
        layers.push_back(layer);
        areas.push_back(area);
    }
    // A particle on a smooth stretch of wall: it stands for spacing^(D-1).
    void add(const Vec<D>& x, const Vec<D>& n, double spacing, int layer) { add(x, n, spacing, layer, std::pow(spacing, D - 1)); }
};

// How many layers of wall particles a patch has, and where the first lies behind its surface.
struct WallLayout {
    int layers;
    double firstLayerOffset;  // in dx
};

// The patch's own `layers` and `firstLayerOffset`; without `layers`, the layout `fromModel` gives
// (its model's, driver/WallLayoutFromModel), a firstLayerOffset named in the patch still
// applying. With `layers` but no `firstLayerOffset`, the offset `offsetOfModel` gives (the
// patch's model's, so that `layers 1` under a wall-force model lies on the wall surface), or 1/2
// where it gives none (the case selects no model for the patch).
WallLayout wallLayout(const Dictionary& patch, const std::function<WallLayout()>& fromModel,
                      const std::function<std::optional<double>()>& offsetOfModel = {});

// Adds the layers of a 2D path of straight faces through `points` (closed: a polygon, the last
// point joined to the first), the normal on the left of the direction of travel for sign +1 and
// on the right for -1; errors (coincident points) name `patch`'s keyword `points`.
void addWallPath(const Dictionary& patch, const std::vector<Vec<2>>& points, bool closed, double sign, double dx, int layers, double offset,
                 WallPatchParticles<2>& walls);

// The wall patch shapes, selected by `type` (each declared once, with its keywords, for the
// generator and -listModels).
template <int D>
using WallPatchRegistry = Registry<WallPatchParticles<D>, const Dictionary&, double, const WallLayout&, const GenerationDomain<D>&>;
template <int D>
WallPatchRegistry<D> makeWallPatchRegistry();

template <int D>
WallPatchParticles<D> generateWallPatch(const Dictionary& patch, double dx, const WallLayout& layout, const GenerationDomain<D>& domain);

}  // namespace sph
