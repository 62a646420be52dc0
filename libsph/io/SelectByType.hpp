// Creates the model a dictionary's `type` word names, from the family's registry; an unknown
// word is reported at the word's file, line and column with the valid names.
#pragma once

#include "io/Dictionary.hpp"

#include <string>
#include <utility>

namespace sph {

template <class Registry, class... Args>
auto selectByType(const Registry& registry, const Dictionary& dict, Args&&... args) {
    const std::string name = dict.get<std::string>("type");
    return registry.create(name, dict.entry("type").tokens().front().where, std::forward<Args>(args)...);
}

}  // namespace sph
