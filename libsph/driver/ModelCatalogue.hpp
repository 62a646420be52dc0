// `-listModels`: every registered model of every family, with its summary, reference and
// coefficients (defaults, meaning), so users need not read the source to learn the choices.
#pragma once

#include <string>

namespace sph {

std::string modelCatalogue();

}  // namespace sph
