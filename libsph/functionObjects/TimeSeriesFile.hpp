// A function object's time series (postProcessing/<name>/<startTime>/<file>): a header line,
// then one line per execution, each flushed as it is written, so a killed run leaves every
// complete line. A failed write (disk full, directory gone) is a FatalError naming the file.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

namespace sph {

class TimeSeriesFile {
public:
    TimeSeriesFile() = default;  // writes nothing (a series the case did not ask for)
    TimeSeriesFile(const std::filesystem::path& directory, const std::string& file, const std::string& header);
    void append(const std::string& line);  // `line` ends without a newline

private:
    std::filesystem::path path_;
    std::ofstream out_;
};

}  // namespace sph
