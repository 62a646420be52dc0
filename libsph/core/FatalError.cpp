#include "core/FatalError.hpp"

namespace sph {

std::string SourceLocation::str() const {
    std::string text = file ? *file : std::string("<unknown>");
    if (line > 0) {
        // Appended piece by piece: GCC 12 warns falsely on ":" + std::string at -O3 (bug 105651).
        (text += ':') += std::to_string(line);
        if (column > 0) (text += ':') += std::to_string(column);
    }
    return text;
}

}  // namespace sph
