// Cell list for few points in a large domain: the generator's walls (1e5 particles in a domain
// of 3e7 cells of dx/2 at dx = 6 mm), whose dense cell arrays cost 9 bytes a cell. Here only the
// points' cells are stored (sorted, with a hash of the rows that hold any), so that memory
// follows the points. The cells, and the order in which a query visits the points, are
// CellLinkedList's without periodic directions: rows of five cells along x, the slower axes
// outer, each cell's points in index order. So a result that depends on the visiting order (the
// generator's tie between two walls' pushes) is the same with either list.
#pragma once

#include "core/Vector.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace sph {

template <int D>
class SparseCellList {
public:
    // For queries within `radius`, over the grid CellLinkedList(lower, upper, radius) has.
    SparseCellList(const Vec<D>& lower, const Vec<D>& upper, double radius);

    // Sorts copies of the points into cells: queries see the positions of this build.
    void build(const std::vector<Vec<D>>& points);

    // Calls visit(j, x - x_j, |x - x_j|^2) for every point j with |x - x_j| < radius, in
    // CellLinkedList's order.
    template <class Visit>
    void forEachNeighbour(const Vec<D>& x, double radius, Visit&& visit) const {
        const double radius2 = radius * radius;
        const std::array<long, D> c = cellCoordinates(x);
        std::array<long, D> offset{};
        for (int d = 1; d < D; ++d) offset[static_cast<std::size_t>(d)] = -reach;
        while (true) {
            if (const Range* row = rowAt(c, offset)) {
                const std::uint64_t rowStart = row->key * static_cast<std::uint64_t>(dims_[0]);
                const std::uint64_t first = rowStart + static_cast<std::uint64_t>(std::max(c[0] - reach, 0L));
                const std::uint64_t last = rowStart + static_cast<std::uint64_t>(std::min(c[0] + reach, dims_[0] - 1));
                for (std::uint32_t k = firstPlaceFrom(*row, first); k < row->end && sortedCell_[k] <= last; ++k) {
                    const Vec<D> r = x - sortedPosition_[k];
                    const double r2 = r.squaredNorm();
                    if (r2 < radius2) visit(sorted_[k], r, r2);
                }
            }
            int d = 1;
            for (; d < D; ++d) {
                if (++offset[static_cast<std::size_t>(d)] <= reach) break;
                offset[static_cast<std::size_t>(d)] = -reach;
            }
            if (d >= D) break;
        }
    }

private:
    static constexpr long reach = 2;  // cells per search radius, as CellLinkedList's
    struct Range {
        std::uint64_t key;  // the row's index among the rows of the grid
        std::uint32_t begin, end;
    };

    // The grid coordinates of the cell holding x, clamped to the grid as CellLinkedList clamps.
    std::array<long, D> cellCoordinates(const Vec<D>& x) const {
        std::array<long, D> c;
        for (int d = 0; d < D; ++d) {
            const auto dd = static_cast<std::size_t>(d);
            const long cd = static_cast<long>(std::floor((x[d] - lower_[d]) * inverseCellSize_));
            c[dd] = std::clamp(cd, 0L, dims_[dd] - 1);
        }
        return c;
    }
    // The row of cells at c + offset (offset along the axes after x), or null where it is
    // outside the grid or holds no point.
    const Range* rowAt(const std::array<long, D>& c, const std::array<long, D>& offset) const;
    // The first place of the row at or after cell `first`.
    std::uint32_t firstPlaceFrom(const Range& row, std::uint64_t first) const;

    Vec<D> lower_;
    double inverseCellSize_;
    std::array<long, D> dims_;
    std::vector<std::uint64_t> sortedCell_;          // cell of each place, ascending
    std::vector<std::uint32_t> sorted_;              // place -> point index
    std::vector<Vec<D>> sortedPosition_;             // positions in cell order
    std::unordered_map<std::uint64_t, Range> rows_;  // row index -> its places
};

}  // namespace sph
