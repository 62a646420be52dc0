#include "io/AtomicFile.hpp"

#include "core/FatalError.hpp"

#include <fstream>
#include <unistd.h>

namespace sph {

void writeAtomically(const std::filesystem::path& file, const std::function<void(const std::filesystem::path&)>& write) {
    std::filesystem::path temporary = file;
    temporary.replace_filename("." + file.filename().string() + ".tmp" + std::to_string(::getpid()));
    try {
        write(temporary);
        std::error_code ec;
        std::filesystem::rename(temporary, file, ec);
        if (ec) throw FatalError("error: cannot rename '" + temporary.string() + "' to '" + file.string() + "': " + ec.message());
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw;
    }
}

void writeTextAtomically(const std::filesystem::path& file, const std::string& text) {
    writeAtomically(file, [&](const std::filesystem::path& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        out << text;
        out.close();
        if (!out) throw FatalError("error: cannot write '" + file.string() + "' (directory not writable, or disk full?)");
    });
}

}  // namespace sph
