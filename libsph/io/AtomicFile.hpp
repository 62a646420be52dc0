// Writes a file under a temporary name in its own directory and renames it into place, so
// the file is either the old one or the complete new one, never a truncated mix. Temporary
// names start with a dot: the solver never takes them for output, even after a kill -9.
#pragma once

#include "core/FatalError.hpp"

#include <filesystem>
#include <functional>
#include <string>

namespace sph {

// `write` produces the file at the path it is given; any exception removes the temporary.
void writeAtomically(const std::filesystem::path& file, const std::function<void(const std::filesystem::path&)>& write);

// A directory filled by `write`, built under a temporary name beside it and renamed into
// place: a reader sees no directory or the complete one. An existing directory of that name
// is replaced (a restart from an earlier time writes over the later times it recomputes).
void writeDirectoryAtomically(const std::filesystem::path& directory, const std::function<void(const std::filesystem::path&)>& write);

// The steps of writeDirectoryAtomically, for writers that are several processes (the ranks of a
// decomposed run): an empty temporary beside `directory`; the filled temporary moved into place;
// and, on failure, the temporary removed and `error` thrown again naming `directory`.
std::filesystem::path temporaryDirectoryFor(const std::filesystem::path& directory);
void moveDirectoryIntoPlace(const std::filesystem::path& temporary, const std::filesystem::path& directory);
[[noreturn]] void abandonDirectory(const std::filesystem::path& temporary, const std::filesystem::path& directory, const FatalError& error);

// Text content, atomically.
void writeTextAtomically(const std::filesystem::path& file, const std::string& text);

}  // namespace sph
