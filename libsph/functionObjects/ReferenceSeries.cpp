#include "functionObjects/ReferenceSeries.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <fstream>

namespace sph {

namespace {

std::vector<std::string> splitCsv(const std::string& line) {
    std::vector<std::string> cells;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        std::string cell = line.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        const auto first = cell.find_first_not_of(" \t\r");
        const auto last = cell.find_last_not_of(" \t\r");
        cells.push_back(first == std::string::npos ? std::string() : cell.substr(first, last - first + 1));
        if (comma == std::string::npos) return cells;
        start = comma + 1;
    }
}

}  // namespace

ReferenceSeries::ReferenceSeries(const Dictionary& dict, const std::filesystem::path& caseDirectory, const std::vector<std::string>& quantities,
                                 Along along)
    : file_(caseDirectory / dict.get<std::string>("file")), quantities_(quantities), along_(along), scale_(dict.getPositiveOrDefault("scale", 1.0)) {
    const std::string abscissa = along == Along::Time ? "time" : "coordinate";
    const std::string timeColumn = dict.get<std::string>(abscissa);
    const auto columns = dict.get<std::vector<std::string>>("columns");
    const double timeScale = dict.getPositiveOrDefault(abscissa + "Scale", 1.0);
    const double valueScale = dict.getOrDefault("valueScale", 1.0);
    const double valueOffset = dict.getOrDefault("valueOffset", 0.0);
    if (columns.size() != quantities.size())
        dict.fail("columns", fmt::format("lists {} columns, but this function object compares {} quantities ({})", columns.size(), quantities.size(),
                                         fmt::join(quantities, ", ")));
    std::ifstream in(file_);
    if (!in) dict.fail("file", fmt::format("cannot read '{}'", file_.string()));
    const auto where = [&](int line) { return fmt::format("{}:{}", file_.string(), line); };
    std::string line;
    int lineNumber = 0;
    std::vector<std::string> header;
    std::vector<std::size_t> indices;  // time column first, then the compared columns
    struct Row {
        double t;
        std::vector<double> values;
        int line;
    };
    std::vector<Row> rows;
    while (std::getline(in, line)) {
        ++lineNumber;
        const auto first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        const std::vector<std::string> cells = splitCsv(line);
        if (header.empty()) {
            header = cells;
            std::vector<std::string> wanted{timeColumn};
            wanted.insert(wanted.end(), columns.begin(), columns.end());
            for (std::size_t k = 0; k < wanted.size(); ++k) {
                const auto found = std::find(header.begin(), header.end(), wanted[k]);
                if (found == header.end())
                    dict.fail(k == 0 ? abscissa : "columns",
                              fmt::format("'{}' has no column '{}'; its columns are: {}", file_.string(), wanted[k], fmt::join(header, ", ")));
                indices.push_back(static_cast<std::size_t>(found - header.begin()));
            }
            continue;
        }
        Row row{0.0, {}, lineNumber};
        for (std::size_t k = 0; k < indices.size(); ++k) {
            double value = 0.0;
            const std::string cell = indices[k] < cells.size() ? cells[indices[k]] : std::string();
            const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
            if (cell.empty() || error != std::errc() || end != cell.data() + cell.size())
                throw FatalError(fmt::format("error: {}: column '{}' holds '{}', not a number", where(lineNumber), header[indices[k]], cell));
            if (k == 0)
                row.t = value * timeScale;
            else
                row.values.push_back(value * valueScale + valueOffset);
        }
        rows.push_back(std::move(row));
    }
    if (header.empty()) throw FatalError(fmt::format("error: '{}' has no header row", file_.string()));
    if (rows.size() < 2)
        throw FatalError(fmt::format("error: '{}' has {} rows of numbers; a reference needs at least 2", file_.string(), rows.size()));
    // A coordinate may run either way, the direction its first two rows take. Rows that step
    // back (digitised curves do) are sorted into place, stably, and the run says so.
    const bool decreasing = along == Along::Coordinate && rows[1].t < rows[0].t;
    std::vector<int> stepsBack;  // lines, in the file's own direction
    for (std::size_t k = 1; k < rows.size(); ++k)
        if (decreasing ? rows[k].t > rows[k - 1].t : rows[k].t < rows[k - 1].t) stepsBack.push_back(rows[k].line);
    if (decreasing) std::reverse(rows.begin(), rows.end());
    if (!stepsBack.empty()) {
        std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.t < b.t; });
        fmt::print("note: {}: {} row{} step{} back in {} (line{} {}{}); the reference is sorted by {}\n", file_.string(), stepsBack.size(),
                   stepsBack.size() == 1 ? "" : "s", stepsBack.size() == 1 ? "s" : "", abscissa, stepsBack.size() == 1 ? "" : "s",
                   fmt::join(stepsBack.begin(), stepsBack.begin() + static_cast<std::ptrdiff_t>(std::min<std::size_t>(stepsBack.size(), 5)), ", "),
                   stepsBack.size() > 5 ? ", ..." : "", abscissa);
    }
    values_.resize(columns.size());
    for (const Row& row : rows) {
        times_.push_back(row.t);
        for (std::size_t c = 0; c < columns.size(); ++c) values_[c].push_back(row.values[c]);
    }
    accumulators_.resize(columns.size());
}

std::optional<std::vector<double>> ReferenceSeries::at(double t) const {
    if (t < times_.front() || t > times_.back()) return std::nullopt;
    const std::size_t upper = std::max<std::size_t>(1, static_cast<std::size_t>(std::lower_bound(times_.begin(), times_.end(), t) - times_.begin()));
    const double width = times_[upper] - times_[upper - 1];  // 0 between rows of the same time
    const double weight = width > 0.0 ? (t - times_[upper - 1]) / width : 1.0;
    std::vector<double> result;
    for (const auto& column : values_) result.push_back(column[upper - 1] + weight * (column[upper] - column[upper - 1]));
    return result;
}

void ReferenceSeries::compare(double t, const std::vector<double>& simulated) {
    const auto reference = at(t);
    if (!reference) return;
    for (std::size_t c = 0; c < simulated.size(); ++c) accumulators_[c].add(simulated[c] - (*reference)[c]);
}

void ReferenceSeries::clear() {
    for (auto& accumulator : accumulators_) accumulator = ErrorAccumulator();
}

std::vector<ReportedError> ReferenceSeries::errors() const {
    std::vector<ReportedError> result;
    for (std::size_t c = 0; c < quantities_.size(); ++c)
        result.push_back({quantities_[c], accumulators_[c].norms(scale_),
                          accumulators_[c].count() > 0
                              ? fmt::format("scale {:g}, {} {}", scale_, accumulators_[c].count(), along_ == Along::Time ? "times" : "points")
                              : fmt::format("no {} of the run within the reference's [{:g}, {:g}]", along_ == Along::Time ? "time" : "point",
                                            times_.front(), times_.back())});
    return result;
}

std::string ReferenceSeries::describe() const {
    return fmt::format("reference {} ({} rows, {} in [{:g}, {:g}])", file_.filename().string(), times_.size(),
                       along_ == Along::Time ? "t" : "coordinate", times_.front(), times_.back());
}

}  // namespace sph
