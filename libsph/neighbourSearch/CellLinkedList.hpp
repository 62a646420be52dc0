// Cell-linked list: a uniform grid of cells half the search radius wide, filled by a counting
// sort (O(N + cells), in parallel). A query visits the 5^D cells around a point, which hug the
// search sphere more closely than 3^D cells a radius wide (1.4x fewer candidates in 2D, 1.7x in
// 3D); in each row the five cells are consecutive, so a row is one contiguous range of the cell
// order. Periodic directions wrap the cells and report the nearest image's separation.
#pragma once

#include "core/Vector.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace sph {

template <int D>
class CellLinkedList {
public:
    static constexpr int reach = 2;  // cells per search radius
    static constexpr int stencilCells = D == 1 ? 5 : D == 2 ? 25 : 125;

    // For queries within `radius`. A periodic direction needs an extent of at least 2.5 radii.
    CellLinkedList(const Vec<D>& lower, const Vec<D>& upper, double radius, const std::array<bool, D>& periodic = {});

    // Sorts copies of the points into cells: queries see the positions of the last build.
    void build(const std::vector<Vec<D>>& points) { build(points, 0, points.size()); }
    // Only points [begin, end) (one wall patch, say); queries report their indices in `points`.
    void build(const std::vector<Vec<D>>& points, std::size_t begin, std::size_t end);

    // Order of the points sorted by cell (for reordering particle storage).
    std::vector<std::uint32_t> cellOrder(const std::vector<Vec<D>>& points) const;

    // The cell-order ranges of the 5^D cells around x: one range per row of five consecutive
    // cells, or one per cell across a periodic x boundary. A plain array, so that a hot loop
    // over it keeps its sums in registers.
    struct Range {
        std::uint32_t begin, end;
    };
    struct StencilRanges {
        std::array<Range, stencilCells> ranges;
        int count = 0;
        const Range* begin() const { return ranges.data(); }
        const Range* end() const { return ranges.data() + count; }
    };
    StencilRanges stencilRanges(const Vec<D>& x) const;
    // The same restricted to the cells with keepCell[cell] != 0 (one entry per cell), in the
    // same order.
    StencilRanges stencilRanges(const Vec<D>& x, const std::vector<std::uint8_t>& keepCell) const;

    // Calls visit(j, x - x_j, |x - x_j|^2) for every point j with |x - x_j| < radius.
    template <class Visit>
    void forEachNeighbour(const Vec<D>& x, double radius, Visit&& visit) const {
        forEachNeighbour(stencilRanges(x), x, radius, visit);
    }
    // The same with the stencil of x's cell computed before (shared by the points of a cell).
    template <class Visit>
    void forEachNeighbour(const StencilRanges& stencil, const Vec<D>& x, double radius, Visit&& visit) const {
        const double radius2 = radius * radius;
        for (const Range& range : stencil) {
            for (std::uint32_t k = range.begin; k < range.end; ++k) {
                Vec<D> r = x - sortedPosition_[k];
                if (anyPeriodic_) nearestImage(r);
                const double r2 = r.squaredNorm();
                if (r2 < radius2) visit(sorted_[k], r, r2);
            }
        }
    }

    // Lists in `out` the places from `first` on in the stencil's ranges whose points lie within
    // sqrt(radius2) of x, and returns how many. No branch per candidate (a third of them are
    // neighbours: a branch would be mispredicted often). Lanes > 1: the squared distances of a
    // range come first, in whole vectors, in `scratch`. `out` keeps room for Lanes places past
    // the last listed, to pad with. Wraps: the nearest image's separation; without it a candidate
    // costs a third fewer instructions, so that callers pick the version once (anyPeriodic()).
    template <std::size_t Lanes, bool Wraps>
    std::size_t listWithin(const StencilRanges& stencil, const std::array<double, D>& x, double radius2, std::size_t first,
                           std::vector<std::uint32_t>& out, std::vector<double>& scratch) const {
        const double* const positions = sortedPosition_.data()->data();  // readable even for an empty list
        const auto distance2To = [&](std::size_t l) {
            double r2 = 0.0;
#pragma GCC unroll 3
            for (int d = 0; d < D; ++d) {
                const double r = separation<Wraps>(x[d] - positions[l * D + d], d);
                r2 += r * r;
            }
            return r2;
        };
        std::size_t count = 0;
        for (const Range& range : stencil) {
            const std::size_t begin = std::max<std::size_t>(range.begin, first);
            if (begin >= range.end) continue;
            const std::size_t candidates = range.end - begin;
            if (out.size() < count + candidates + Lanes) out.resize(2 * (count + candidates + Lanes));
            if constexpr (Lanes == 1) {
                for (std::size_t l = begin; l < range.end; ++l) {
                    out[count] = static_cast<std::uint32_t>(l);
                    count += distance2To(l) < radius2;
                }
            } else {
                // Whole vectors: positions are readable past the last place.
                static_assert(readablePastEnd >= Lanes - 1);
                const std::size_t inLanes = (candidates + Lanes - 1) / Lanes * Lanes;
                if (scratch.size() < inLanes) scratch.resize(2 * inLanes);
                double* const r2s = scratch.data();
#pragma omp simd
                for (std::size_t c = 0; c < inLanes; ++c) r2s[c] = distance2To(begin + c);
                for (std::size_t c = 0; c < candidates; ++c) {
                    out[count] = static_cast<std::uint32_t>(begin + c);
                    count += r2s[c] < radius2;
                }
            }
        }
        return count;
    }
    bool anyPeriodic() const { return anyPeriodic_; }
    // The separation r along direction d, or with Wraps its nearest image's: r - L nearbyint(r / L)
    // with L the period (1/L taken as 0 where not periodic, so that there is no branch).
    template <bool Wraps>
    double separation(double r, int d) const {
        if constexpr (Wraps) r -= period_[d] * std::nearbyint(r * inversePeriod_[d]);
        return r;
    }

    // Positions in cell order (of the last build); each pair once: the neighbours of place k
    // at later places l are those of stencilRanges(sortedPosition(k)) with l > k. Places up to
    // readablePastEnd beyond the last hold zeros, so that a loop in vector lanes may read whole
    // vectors past the end of any range.
    static constexpr std::size_t readablePastEnd = 7;
    const Vec<D>& sortedPosition(std::size_t k) const { return sortedPosition_[k]; }

    // The points in cell order: place k holds point sortedIndex(k).
    std::size_t pointCount() const { return sorted_.size(); }
    std::uint32_t sortedIndex(std::size_t k) const { return sorted_[k]; }
    // The cell of place k: consecutive places in one cell share their stencil ranges, and a
    // list built with the same grid (domain, radius, periodicity) numbers its cells the same.
    std::uint32_t cellAt(std::size_t k) const { return sortedCell_[k]; }

    // Shortest separation vector under the periodic directions.
    void nearestImage(Vec<D>& r) const {
        for (int d = 0; d < D; ++d) r[d] = separation<true>(r[d], d);
    }

    std::size_t cellCount() const { return cellStart_.size() - 1; }

    // The grid's integer coordinates and index of the cell holding x (wrapped or clamped, as a
    // build files it), and the coordinate of the face between cells k - 1 and k along d: a rank's
    // part of space (libsph/parallel) is a block of whole cells.
    std::array<int, D> cellCoordinates(const Vec<D>& x) const {
        std::array<int, D> c;
        for (int d = 0; d < D; ++d) {
            // Points outside the grid wrap (periodic) or are clamped to its edge cells: never out of range.
            const auto dd = static_cast<std::size_t>(d);
            const int cd = static_cast<int>(std::floor((x[d] - lower_[d]) * inverseCellSizes_[d]));
            c[dd] = periodic_[dd] ? ((cd % dims_[dd]) + dims_[dd]) % dims_[dd] : std::clamp(cd, 0, dims_[dd] - 1);
        }
        return c;
    }
    std::size_t cellIndex(const Vec<D>& x) const {
        const std::array<int, D> c = cellCoordinates(x);
        std::size_t index = 0;
        for (int d = D - 1; d >= 0; --d)
            index = index * static_cast<std::size_t>(dims_[static_cast<std::size_t>(d)]) + static_cast<std::size_t>(c[static_cast<std::size_t>(d)]);
        return index;
    }
    double cellFace(int d, long k) const { return lower_[d] + static_cast<double>(k) / inverseCellSizes_[d]; }
    // The face nearest to a coordinate along d, as k of cellFace.
    long nearestCellFace(int d, double coordinate) const { return std::lround((coordinate - lower_[d]) * inverseCellSizes_[d]); }

    // From the next build on, keeps which cells have a point of the list in their stencil, so that
    // a query from a cell with none can be skipped (the fluid-wall pass: most fluid cells have no
    // wall particle within reach). A build then costs 5^(D-1) row fills per cell with points more.
    void markCellsNearPoints();
    // Whether a point of the last build lies in the stencil of `cell` (after markCellsNearPoints).
    bool anyPointNear(std::uint32_t cell) const { return pointNear_[cell] != 0; }
    // The same for the cell of x: false where forEachNeighbour(x, ...) would visit no point
    // (always true on a list that does not keep the marks).
    bool anyPointNear(const Vec<D>& x) const { return pointNear_.empty() || pointNear_[cellIndex(x)] != 0; }

private:
    void markCellsNear();

    Vec<D> lower_;
    Vec<D> inverseCellSizes_;  // per direction: a periodic direction stretches its cells to fit
    std::array<int, D> dims_;
    std::array<bool, D> periodic_;
    bool anyPeriodic_ = false;
    std::array<double, D> period_{}, inversePeriod_{};  // 0 where not periodic
    std::vector<std::uint32_t> cellStart_;              // size cells + 1
    std::vector<std::uint32_t> sorted_;                 // cell order -> point index
    std::vector<Vec<D>> sortedPosition_;                // positions in cell order, read contiguously by queries
    std::vector<std::uint32_t> sortedCell_;             // cell of each place
    std::vector<std::uint8_t> pointNear_;               // per cell, when kept: 1 if a point lies in its stencil
    // Scratch of build, kept so as not to allocate it again every step.
    std::vector<std::uint32_t> cellOf_;                       // cell of each point
    std::vector<std::uint32_t> threadTotals_;                 // per thread: the points in its range of cells
    std::vector<std::vector<std::uint32_t>> straysOfThread_;  // per thread: points of its block in others' cells
    std::vector<std::size_t> strayCountOfThread_;             // per thread: how many of its list are strays (never shrunk)
    std::vector<std::size_t> firstCellOfThread_;              // per thread, and the cell count: where its range of cells starts
};

}  // namespace sph
