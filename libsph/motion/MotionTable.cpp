#include "motion/MotionTable.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace sph {

template <int D>
MotionTable<D>::MotionTable(const Dictionary& dict, const std::string& caseDirectory) {
    const std::string name = dict.get<std::string>("file");
    file_ = (std::filesystem::path(caseDirectory) / name).string();
    std::ifstream in(file_);
    if (!in) dict.fail("file", "cannot open the motion table '" + file_ + "'");
    std::string line;
    int lineNumber = 0;
    while (std::getline(in, line)) {
        ++lineNumber;
        std::replace(line.begin(), line.end(), ',', ' ');
        if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
        std::istringstream row(line);
        std::vector<double> values;
        for (double v; row >> v;) values.push_back(v);
        if (!row.eof()) {
            if (times_.empty() && values.empty()) continue;  // a header line
            throw FatalError(fmt::format("error: motion table '{}', line {}: expected numbers, found '{}'", file_, lineNumber, line));
        }
        if (values.size() != static_cast<std::size_t>(D + 1))
            throw FatalError(fmt::format("error: motion table '{}', line {}: expected {} columns (t and a {}D displacement), found {}", file_,
                                         lineNumber, D + 1, D, values.size()));
        if (!times_.empty() && !(values[0] > times_.back()))
            throw FatalError(fmt::format("error: motion table '{}', line {}: time {:g} does not increase", file_, lineNumber, values[0]));
        times_.push_back(values[0]);
        Vec<D> d;
        for (int k = 0; k < D; ++k) d[k] = values[static_cast<std::size_t>(k + 1)];
        displacements_.push_back(d);
    }
    if (times_.size() < 2) dict.fail("file", "the motion table '" + file_ + "' needs at least two rows");
}

template <int D>
std::string MotionTable<D>::describe() const {
    return fmt::format("table: {} ({} rows, t from {:g} to {:g})", file_, times_.size(), times_.front(), times_.back());
}

template <int D>
Vec<D> MotionTable<D>::slope(std::size_t k) const {
    return (displacements_[k + 1] - displacements_[k]) / (times_[k + 1] - times_[k]);
}

template <int D>
Kinematics<D> MotionTable<D>::at(const Vec<D>& x0, const Vec<D>&, double t) const {
    const std::size_t k = static_cast<std::size_t>(
        std::clamp<long>(std::upper_bound(times_.begin(), times_.end(), t) - times_.begin() - 1, 0, static_cast<long>(times_.size()) - 2));
    const double fraction = (t - times_[k]) / (times_[k + 1] - times_[k]);
    const Vec<D> position = x0 + displacements_[k] + fraction * (displacements_[k + 1] - displacements_[k]);
    // Acceleration: change of slope between the midpoints of the intervals around t.
    const double middle = 0.5 * (times_[k] + times_[k + 1]);
    const bool earlierExists = k > 0, laterExists = k + 2 < times_.size();
    const std::size_t other = (t < middle && earlierExists) || !laterExists ? (earlierExists ? k - 1 : k) : k + 1;
    Vec<D> acceleration = Vec<D>::Zero();
    if (other != k) {
        const double otherMiddle = 0.5 * (times_[other] + times_[other + 1]);
        acceleration = (slope(k) - slope(other)) / (middle - otherMiddle);
    }
    return {position, slope(k), acceleration};
}

template <int D>
void MotionTable<D>::checkCovers(double startTime, double endTime) const {
    if (times_.front() > startTime || times_.back() < endTime)
        throw FatalError(fmt::format("error: motion table '{}' covers t from {:g} to {:g}, but the run goes from {:g} to {:g}", file_, times_.front(),
                                     times_.back(), startTime, endTime));
}

template class MotionTable<1>;
template class MotionTable<2>;
template class MotionTable<3>;

}  // namespace sph
