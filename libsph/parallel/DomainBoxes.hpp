// Which rank owns which part of space: one box per rank, the boxes of a recursive coordinate
// bisection, tiling all of space. A particle belongs to the rank whose box holds its position,
// by one half-open rule [lower, upper) applied the same way on every rank (never a partitioner's
// own lists, which disagree with its boxes for points on a cut). Outer faces lie at infinity,
// but in a periodic direction, where they are the domain's faces, so that distances across the
// seam are measured to the images of the boxes and not to an infinite slab.
// Boxes of whole cells (alignToCells) decide ownership by a particle's cell instead, as the
// neighbour search files it: every cell then lies on one rank, whatever rounding at a face does.
#pragma once

#include "core/Vector.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace sph::parallel {

template <int D>
struct RankBox {
    Vec<D> lower;
    Vec<D> upper;
};

template <int D>
class DomainBoxes {
public:
    // period[d] is the domain's length in a periodic direction d, 0 in the others.
    DomainBoxes(std::vector<RankBox<D>> boxes, const Vec<D>& period) : boxes_(std::move(boxes)), period_(period) {}

    int ranks() const { return static_cast<int>(boxes_.size()); }
    const RankBox<D>& box(int rank) const { return boxes_[static_cast<std::size_t>(rank)]; }
    const Vec<D>& period() const { return period_; }

    // -1 only for a point outside every box: a non-finite position.
    int ownerOf(const Vec<D>& x) const {
        if (cellOf_) return ownerOfCell(x);
        for (std::size_t r = 0; r < boxes_.size(); ++r) {
            bool inside = true;
            for (int d = 0; d < D; ++d) inside = inside && boxes_[r].lower[d] <= x[d] && x[d] < boxes_[r].upper[d];
            if (inside) return static_cast<int>(r);
        }
        return -1;
    }

    // Shortest distance from x to the rank's box, over the periodic images.
    double distanceToBox(const Vec<D>& x, int rank) const {
        const RankBox<D>& b = box(rank);
        double squared = 0.0;
        for (int d = 0; d < D; ++d) {
            auto gap = [&](double at) { return std::max({b.lower[d] - at, 0.0, at - b.upper[d]}); };
            double g = gap(x[d]);
            if (period_[d] > 0.0) g = std::min({g, gap(x[d] - period_[d]), gap(x[d] + period_[d])});
            squared += g * g;
        }
        return std::sqrt(squared);
    }

    // Whether two ranks' boxes come within `width` of each other (over the periodic images).
    bool within(int a, int b, double width) const {
        double squared = 0.0;
        for (int d = 0; d < D; ++d) {
            const RankBox<D>&p = box(a), &q = box(b);
            auto gap = [&](double shift) { return std::max({q.lower[d] + shift - p.upper[d], 0.0, p.lower[d] - q.upper[d] - shift}); };
            double g = gap(0.0);
            if (period_[d] > 0.0) g = std::min({g, gap(period_[d]), gap(-period_[d])});
            squared += g * g;
        }
        return squared <= width * width;
    }

    // Moves every finite face to the nearest face of the grid's cells and decides ownership by
    // the cell a particle lies in. `grid` is a neighbour search's cell list (CellLinkedList) and
    // must outlive the boxes.
    template <class Grid>
    void alignToCells(const Grid& grid) {
        blocks_.assign(boxes_.size(), {});
        for (std::size_t r = 0; r < boxes_.size(); ++r)
            for (int d = 0; d < D; ++d) {
                auto& [lower, upper] = blocks_[r][static_cast<std::size_t>(d)];
                lower = std::numeric_limits<long>::min(), upper = std::numeric_limits<long>::max();
                if (std::isfinite(boxes_[r].lower[d])) boxes_[r].lower[d] = grid.cellFace(d, lower = grid.nearestCellFace(d, boxes_[r].lower[d]));
                if (std::isfinite(boxes_[r].upper[d])) boxes_[r].upper[d] = grid.cellFace(d, upper = grid.nearestCellFace(d, boxes_[r].upper[d]));
            }
        cellOf_ = [&grid](const Vec<D>& x) { return grid.cellCoordinates(x); };
    }

private:
    int ownerOfCell(const Vec<D>& x) const {
        if (!x.allFinite()) return -1;
        const std::array<int, D> cell = cellOf_(x);
        for (std::size_t r = 0; r < blocks_.size(); ++r) {
            bool inside = true;
            for (std::size_t d = 0; d < D; ++d) inside = inside && blocks_[r][d].first <= cell[d] && cell[d] < blocks_[r][d].second;
            if (inside) return static_cast<int>(r);
        }
        return -1;
    }

    std::vector<RankBox<D>> boxes_;
    Vec<D> period_;
    std::vector<std::array<std::pair<long, long>, D>> blocks_;  // per rank, per direction: cells [first, second)
    std::function<std::array<int, D>(const Vec<D>&)> cellOf_;
};

}  // namespace sph::parallel
