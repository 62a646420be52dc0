// What a function object needs where each process holds a share of the particles (a decomposed
// run, libsph/parallel): sums and extrema over the processes, the candidates each offers for a
// choice that every process must make alike, and whether this process writes the object's
// files. Each object measures on the particles its process owns (FluidSystemView::ownsFluid)
// and the sample points it answers for (FluidSystemView::answersFor), and combines here.
// This base class is the serial run's: one process, nothing to combine, and it writes.
#pragma once

#include "core/ExactSum.hpp"

#include <functional>
#include <span>
#include <vector>

namespace sph {

class Reductions {
public:
    virtual ~Reductions() = default;
    static const Reductions& oneProcess() {
        static const Reductions serial;
        return serial;
    }

    virtual bool writesFiles() const { return true; }
    // Collective, in place, the result on every process. Exact sums, so that the result does
    // not depend on how the particles are shared.
    virtual void sum(std::span<ExactSum>) const {}
    virtual void max(std::span<double>) const {}
    // Collective: every process's values, the first process's first, on every process.
    virtual std::vector<double> gather(std::span<const double> mine) const { return {mine.begin(), mine.end()}; }
    // Collective: runs `body`; a FatalError on any process stops every process with its message
    // (so that no process goes on to the next collective step alone).
    virtual void together(const std::function<void()>& body) const { body(); }

    // The sum and the largest of one number each.
    double sum(double mine) const {
        ExactSum total;
        total.add(mine);
        sum(std::span<ExactSum>(&total, 1));
        return total.value();
    }
    double max(double mine) const {
        max(std::span<double>(&mine, 1));
        return mine;
    }
};

}  // namespace sph
