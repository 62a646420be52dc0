// Cell-linked list: a uniform grid of cells no smaller than the kernel support, filled by a
// counting sort (O(N)). A query visits the 3^D cells around a point; in each row the three
// neighbouring cells are consecutive, so a row is one contiguous index range. Periodic
// directions wrap the cells and report the nearest image's separation.
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
    // A periodic direction needs an extent of at least three cells.
    CellLinkedList(const Vec<D>& lower, const Vec<D>& upper, double cellSize, const std::array<bool, D>& periodic = {});

    // Sorts the points into cells; the list refers to `points` until the next build.
    void build(const std::vector<Vec<D>>& points) { build(points, 0, points.size()); }
    // Only points [begin, end) (one wall patch, say); queries report their indices in `points`.
    void build(const std::vector<Vec<D>>& points, std::size_t begin, std::size_t end);

    // Order of the points sorted by cell (for reordering particle storage).
    std::vector<std::uint32_t> cellOrder(const std::vector<Vec<D>>& points) const;

    // Calls visit(j, x - x_j, |x - x_j|^2) for every point j with |x - x_j| < radius.
    template <class Visit>
    void forEachNeighbour(const Vec<D>& x, double radius, Visit&& visit) const {
        const std::array<int, D> c = cellCoordinates(x);
        const double radius2 = radius * radius;
        std::array<int, D> offset{};
        for (int d = 1; d < D; ++d) offset[static_cast<std::size_t>(d)] = -1;
        const auto visitRange = [&](long first, long last) {
            for (std::uint32_t k = cellStart_[static_cast<std::size_t>(first)]; k < cellStart_[static_cast<std::size_t>(last) + 1]; ++k) {
                const std::uint32_t j = sorted_[k];
                Vec<D> r = x - (*points_)[j];
                if (anyPeriodic_) nearestImage(r);
                const double r2 = r.squaredNorm();
                if (r2 < radius2) visit(j, r, r2);
            }
        };
        while (true) {
            bool inside = true;
            long rowCell = 0;
            for (int d = D - 1; d >= 1; --d) {
                const auto dd = static_cast<std::size_t>(d);
                int cd = c[dd] + offset[dd];
                if (periodic_[dd]) cd = (cd + dims_[dd]) % dims_[dd];
                if (cd < 0 || cd >= dims_[dd]) inside = false;
                rowCell = rowCell * dims_[dd] + cd;
            }
            if (inside) {
                if (periodic_[0]) {
                    for (int dx = -1; dx <= 1; ++dx) {
                        const long cell = rowCell * dims_[0] + (c[0] + dx + dims_[0]) % dims_[0];
                        visitRange(cell, cell);
                    }
                } else {
                    visitRange(rowCell * dims_[0] + std::max(c[0] - 1, 0), rowCell * dims_[0] + std::min(c[0] + 1, dims_[0] - 1));
                }
            }
            int d = 1;
            for (; d < D; ++d) {
                if (++offset[static_cast<std::size_t>(d)] <= 1) break;
                offset[static_cast<std::size_t>(d)] = -1;
            }
            if (d >= D) break;
        }
    }

    // Shortest separation vector under the periodic directions.
    void nearestImage(Vec<D>& r) const {
        for (int d = 0; d < D; ++d)
            if (periodic_[static_cast<std::size_t>(d)]) r[d] -= extent_[d] * std::round(r[d] / extent_[d]);
    }

    double cellSize() const { return cellSize_; }
    std::size_t cellCount() const { return cellStart_.size() - 1; }

private:
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
        for (int d = D - 1; d >= 0; --d) index = index * static_cast<std::size_t>(dims_[static_cast<std::size_t>(d)]) + static_cast<std::size_t>(c[static_cast<std::size_t>(d)]);
        return index;
    }

    Vec<D> lower_;
    Vec<D> extent_;
    double cellSize_;
    Vec<D> inverseCellSizes_;  // per direction: a periodic direction stretches its cells to fit
    std::array<int, D> dims_;
    std::array<bool, D> periodic_;
    bool anyPeriodic_ = false;
    std::vector<std::uint32_t> cellStart_;  // size cells + 1
    std::vector<std::uint32_t> sorted_;
    const std::vector<Vec<D>>* points_ = nullptr;
};

}  // namespace sph
