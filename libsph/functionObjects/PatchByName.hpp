// The wall patch a function object names: an error at `keyword` listing the case's patches when
// none has that name (before the first step).
#pragma once

#include "io/Dictionary.hpp"
#include "physics/FluidSystemView.hpp"

#include <fmt/format.h>

#include <string>
#include <vector>

namespace sph {

template <int D>
const Patch<D>& patchByName(const Dictionary& dict, const std::string& keyword, const std::string& name, const FluidSystemView<D>& system) {
    std::vector<std::string> names;
    for (const Patch<D>& patch : system.patches) {
        if (patch.name == name) return patch;
        names.push_back(patch.name);
    }
    dict.fail(keyword, fmt::format("no patch '{}'; the patches are: {}", name, fmt::join(names, ", ")));
}

}  // namespace sph
