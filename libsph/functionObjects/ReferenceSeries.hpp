// A reference time series a function object is compared with, read from a CSV file of the case
// (`#` comment lines, one header row, then numbers), interpolated linearly in time. Each
// execution inside the file's time range adds sim - ref per column to that column's error
// norms (ErrorNorms.hpp); executions outside it are not compared.
//   reference
//   {
//       file        "martinMoyce1952Front.csv";  // relative to the case directory
//       time        T;              // the time column
//       columns     (Z);            // one per compared quantity, in the function object's order
//       timeScale   0.0534;         // seconds per unit of the file's time (default 1)
//       valueScale  0.05715;        // units of the quantity per unit of the file's values (default 1)
//       valueOffset 0;              // added after scaling, in the quantity's units (default 0): a
//                                   // wave gauge at the floor compares with elevations about the still level
//       scale       0.05715;        // errors are divided by this (default 1: absolute errors)
//   }
// A missing file or column or a cell that is not a number is an error naming the file, line and
// column, before the first step. Rows that step back in time (digitised curves do) are sorted
// into place, stably, with a note naming their lines; rows of the same time make a step.
// A reference profile (along a line, Along::Coordinate) reads `coordinate` and
// `coordinateScale` instead of `time` and `timeScale`; its coordinate may increase or decrease
// (the direction of its first two rows), and is sorted the same way.
#pragma once

#include "functionObjects/ErrorNorms.hpp"
#include "io/Dictionary.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sph {

class ReferenceSeries {
public:
    // `quantities` names what is compared, one per column (for the error summary); their count
    // must match the columns' count.
    enum class Along { Time, Coordinate };
    ReferenceSeries(const Dictionary& dict, const std::filesystem::path& caseDirectory, const std::vector<std::string>& quantities,
                    Along along = Along::Time);

    // The reference values at time (or coordinate) t, scaled; none outside the file's range.
    std::optional<std::vector<double>> at(double t) const;
    // Compares `simulated` (one value per column) with the reference at t.
    void compare(double t, const std::vector<double>& simulated);
    void clear();  // forgets what was compared (a profile compares the latest execution only)
    std::vector<ReportedError> errors() const;
    std::string describe() const;

private:
    std::filesystem::path file_;
    std::vector<std::string> quantities_;
    Along along_;
    std::vector<double> times_;                // or coordinates, non-decreasing
    std::vector<std::vector<double>> values_;  // [column][row]
    double scale_;
    std::vector<ErrorAccumulator> accumulators_;
};

// The errors of an optional reference: none without one.
inline std::vector<ReportedError> errorsOf(const std::optional<ReferenceSeries>& reference) {
    return reference ? reference->errors() : std::vector<ReportedError>{};
}

}  // namespace sph
