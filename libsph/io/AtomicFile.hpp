// Writes a file under a temporary name in its own directory and renames it into place, so
// the file is either the old one or the complete new one, never a truncated mix.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace sph {

// `write` produces the file at the path it is given; any exception removes the temporary.
void writeAtomically(const std::filesystem::path& file, const std::function<void(const std::filesystem::path&)>& write);

// Text content, atomically.
void writeTextAtomically(const std::filesystem::path& file, const std::string& text);

}  // namespace sph
