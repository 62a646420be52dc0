#include "io/AtomicFile.hpp"

#include "core/FatalError.hpp"

#include <fstream>
#include <unistd.h>

namespace sph {

namespace {

// ".<name>.<tag><pid>", the name shortened where the whole would pass the 255 bytes a file
// name may have (a case named with 250 characters writes <case>.pvd).
std::filesystem::path hiddenSibling(const std::filesystem::path& path, const std::string& tag) {
    constexpr std::size_t maxName = 255;
    const std::string suffix = "." + tag + std::to_string(::getpid());
    std::string name = path.filename().string();
    if (name.size() + suffix.size() + 1 > maxName) name.resize(maxName - suffix.size() - 1);
    std::filesystem::path sibling = path;
    sibling.replace_filename("." + name + suffix);
    return sibling;
}

void throwOnError(const std::error_code& ec, const std::string& what) {
    if (ec) throw FatalError("error: cannot " + what + ": " + ec.message());
}

}  // namespace

void writeAtomically(const std::filesystem::path& file, const std::function<void(const std::filesystem::path&)>& write) {
    const std::filesystem::path temporary = hiddenSibling(file, "tmp");
    try {
        write(temporary);
        std::error_code ec;
        std::filesystem::rename(temporary, file, ec);
        throwOnError(ec, "rename '" + temporary.string() + "' to '" + file.string() + "'");
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw;
    }
}

std::filesystem::path temporaryDirectoryFor(const std::filesystem::path& directory) {
    const std::filesystem::path temporary = hiddenSibling(directory, "tmp");
    std::error_code ec;
    std::filesystem::remove_all(temporary, ec);
    std::filesystem::create_directories(temporary, ec);
    throwOnError(ec, "create the directory '" + temporary.string() + "' (directory not writable?)");
    return temporary;
}

void moveDirectoryIntoPlace(const std::filesystem::path& temporary, const std::filesystem::path& directory) {
    const std::filesystem::path replaced = hiddenSibling(directory, "old");
    std::error_code ec;
    const bool exists = std::filesystem::exists(directory, ec);
    if (exists) {
        std::filesystem::rename(directory, replaced, ec);
        throwOnError(ec, "move the old '" + directory.string() + "' aside");
    }
    std::filesystem::rename(temporary, directory, ec);
    throwOnError(ec, "rename '" + temporary.string() + "' to '" + directory.string() + "'");
    if (exists) std::filesystem::remove_all(replaced, ec);
}

void abandonDirectory(const std::filesystem::path& temporary, const std::filesystem::path& directory, const FatalError& error) {
    std::error_code ignored;
    std::filesystem::remove_all(temporary, ignored);
    throw FatalError(std::string(error.what()) + "\n    while writing '" + directory.string() + "'; what was written before it is complete");
}

void writeDirectoryAtomically(const std::filesystem::path& directory, const std::function<void(const std::filesystem::path&)>& write) {
    const std::filesystem::path temporary = temporaryDirectoryFor(directory);
    try {
        write(temporary);
        moveDirectoryIntoPlace(temporary, directory);
    } catch (const FatalError& error) {
        abandonDirectory(temporary, directory, error);
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
