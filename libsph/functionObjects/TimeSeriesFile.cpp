#include "functionObjects/TimeSeriesFile.hpp"

#include "core/FatalError.hpp"

#include <fmt/format.h>

namespace sph {

TimeSeriesFile::TimeSeriesFile(const std::filesystem::path& directory, const std::string& file, const std::string& header) : path_(directory / file) {
    std::error_code ec;
    std::filesystem::create_directories(directory, ec);
    if (std::filesystem::exists(path_, ec)) fmt::print("Replacing {} (written by an earlier run from the same start time)\n", path_.string());
    out_.open(path_);
    if (!out_) throw FatalError("error: cannot create '" + path_.string() + "' (directory not writable?)");
    append(header);
}

void TimeSeriesFile::append(const std::string& line) {
    if (!out_.is_open()) return;
    out_ << line << '\n' << std::flush;
    if (!out_) throw FatalError("error: cannot write '" + path_.string() + "' (disk full, or the directory removed?)");
}

}  // namespace sph
