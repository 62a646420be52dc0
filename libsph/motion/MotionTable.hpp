// Rigid translation read from a table: a text file of rows `t dx dy [dz]` (displacement of the
// patch from its initial position; commas or blanks; lines starting with # and a header line
// are skipped), interpolated linearly in time. The velocity is the slope of the current
// interval; the acceleration interpolates the change of slope between interval midpoints.
// The table must cover the run (checked before the first step).
// Example (a patch's motion):   motion { type table; file "constant/pistonMotion.csv"; }
#pragma once

#include "motion/PatchMotion.hpp"

#include <vector>

namespace sph {

template <int D>
class MotionTable : public PatchMotion<D> {
public:
    MotionTable(const Dictionary& dict, const std::string& caseDirectory);
    std::string describe() const override;
    Kinematics<D> at(const Vec<D>& x0, const Vec<D>& n0, double t) const override;
    void checkCovers(double startTime, double endTime) const override;

private:
    Vec<D> slope(std::size_t interval) const;
    std::string file_;
    std::vector<double> times_;
    std::vector<Vec<D>> displacements_;
};

}  // namespace sph
