// The ParaView collection (.pvd) at the case root: one DataSet per written time and part
// (fluid, walls), so ParaView opens the case as one time series of two blocks. It is rewritten
// atomically after each complete write, so it only ever lists complete files.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sph {

class PvdCollection {
public:
    explicit PvdCollection(std::filesystem::path file) : file_(std::move(file)) {}

    // Lists `files` (relative to the .pvd's directory) at `time`, one part each, and rewrites the file.
    void add(double time, const std::vector<std::string>& files);

private:
    struct DataSet {
        double time;
        int part;
        std::string file;
    };
    std::filesystem::path file_;
    std::vector<DataSet> dataSets_;
};

}  // namespace sph
