#include "core/FatalError.hpp"

namespace sph {

std::string SourceLocation::str() const {
    std::string text = file ? *file : std::string("<unknown>");
    if (line > 0) {
        text += ":" + std::to_string(line);
        if (column > 0) text += ":" + std::to_string(column);
    }
    return text;
}

}  // namespace sph
