// The one exception type for errors a user can fix: bad input, a run that blew up.
// The message is complete (file, line, keyword, what was found, what is valid); main()
// prints it and exits non-zero.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

namespace sph {

// Where a token came from; file is shared by every token of one file.
struct SourceLocation {
    std::shared_ptr<const std::string> file;
    int line = 0;
    int column = 0;

    std::string str() const;  // "file:line:column", or "file" when no line is known
};

class FatalError : public std::runtime_error {
public:
    explicit FatalError(const std::string& message) : std::runtime_error(message) {}
    FatalError(const SourceLocation& where, const std::string& message) : std::runtime_error(where.str() + ": error: " + message) {}
};

}  // namespace sph
