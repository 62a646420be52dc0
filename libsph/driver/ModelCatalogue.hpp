// `-listModels`: every registered model of every family, with its summary, reference and
// coefficients (defaults, meaning), so users need not read the source to learn the choices.
#pragma once

#include <string>

namespace sph {

// Every family, or the one named (kernel, density, viscosity, densityDiffusion, particleShifting,
// equationOfState, boundary, motion, integrator, functionObject, analytic, fluidRegion,
// wallPatch); std::invalid_argument naming the valid ones for another name.
std::string modelCatalogue(const std::string& family = "");

}  // namespace sph
