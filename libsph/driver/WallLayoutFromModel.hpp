// The layout of wall particles a patch's model needs, for a wall patch of
// system/generateParticlesDict that names no `layers`: the generator then reads the patch's model
// in constant/boundaryProperties and the kernel in system/sphSchemes, so a case switches wall
// model by one word there and a rerun of generateParticles -overwrite.
//   models whose particles enter the kernel sums (dummyParticles, dynamicBoundary):
//       the fewest layers that fill the support behind the wall, ceil(support/dx - 1/2),
//       the first dx/2 behind the wall surface (firstLayerOffset 0.5);
//   wall-force models (deficiencyCorrection..., monaghanKajtar, lennardJones):
//       one layer on the wall surface (layers 1; firstLayerOffset 0).
// A `firstLayerOffset` the patch names still applies; a patch that names `layers` keeps them and
// takes the model's offset where it names none (`offsetOf`).
#pragma once

#include "generation/WallPatches.hpp"
#include "io/Dictionary.hpp"
#include "physics/FluidProperties.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace sph {

template <int D>
class WallLayoutFromModel {
public:
    WallLayoutFromModel(std::filesystem::path caseDirectory, double dx, const FluidProperties<D>& properties);

    // The layout for patch `name` of generateParticlesDict (`patch`, for the error's location),
    // and a note saying why. The case's dictionaries are read at the first call.
    WallLayout operator()(const std::string& name, const Dictionary& patch, std::string& note);
    // The first layer's offset the model of patch `name` needs (a note where it is not the usual
    // 1/2); none where the case selects no model for it.
    std::optional<double> offsetOf(const std::string& name, std::string& note);

private:
    // The case's entry for patch `name` in constant/boundaryProperties: null where there is none.
    const Dictionary* modelOf(const std::string& name);
    WallLayout layoutOf(const Dictionary& modelDict, std::string& note) const;

    std::filesystem::path caseDirectory_;
    double dx_;
    FluidProperties<D> properties_;
    std::optional<Dictionary> boundaryDict_;
    double h_ = 0.0;
    double support_ = 0.0;
    std::string viscosity_;  // the type in system/sphSchemes: a model's defaults may follow it (noSlip)
};

}  // namespace sph
