#include "neighbourSearch/SparseCellList.hpp"

#include "core/FatalError.hpp"
#include "neighbourSearch/CellLinkedList.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

namespace sph {

template <int D>
SparseCellList<D>::SparseCellList(const Vec<D>& lower, const Vec<D>& upper, double radius) : lower_(lower) {
    static_assert(reach == CellLinkedList<D>::reach);
    const double cellSize = radius / CellLinkedList<D>::reach;  // as CellLinkedList computes it, so that the cells are the same
    inverseCellSize_ = 1.0 / cellSize;
    double cellCount = 1.0;
    for (int d = 0; d < D; ++d) {
        const auto dd = static_cast<std::size_t>(d);
        const double cells = std::max(1.0, std::ceil((upper[d] - lower[d]) / cellSize));
        cellCount *= cells;
        dims_[dd] = static_cast<long>(cells);
    }
    // Cells are numbered by 64-bit integers.
    if (!(cellCount < 9.2e18))
        throw FatalError(
            fmt::format("error: the domain from ({:g}) to ({:g}) would need {:.3g} neighbour-search cells of size {:g}: "
                        "the spacing is too small for the domain, or the domain too large",
                        fmt::join(lower.data(), lower.data() + D, " "), fmt::join(upper.data(), upper.data() + D, " "), cellCount, cellSize));
}

template <int D>
void SparseCellList<D>::build(const std::vector<Vec<D>>& points) {
    std::vector<std::uint64_t> cellOf(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
        const std::array<long, D> c = cellCoordinates(points[k]);
        std::uint64_t cell = 0;
        for (int d = D - 1; d >= 0; --d)
            cell = cell * static_cast<std::uint64_t>(dims_[static_cast<std::size_t>(d)]) + static_cast<std::uint64_t>(c[static_cast<std::size_t>(d)]);
        cellOf[k] = cell;
    }
    // By cell, each cell's points in index order: CellLinkedList's counting sort is stable.
    sorted_.resize(points.size());
    std::iota(sorted_.begin(), sorted_.end(), 0U);
    std::stable_sort(sorted_.begin(), sorted_.end(), [&](std::uint32_t a, std::uint32_t b) { return cellOf[a] < cellOf[b]; });
    sortedCell_.resize(points.size());
    sortedPosition_.resize(points.size());
    rows_.clear();
    const auto rowLength = static_cast<std::uint64_t>(dims_[0]);
    for (std::uint32_t k = 0; k < sorted_.size(); ++k) {
        sortedCell_[k] = cellOf[sorted_[k]];
        sortedPosition_[k] = points[sorted_[k]];
        const std::uint64_t row = sortedCell_[k] / rowLength;
        const auto [at, added] = rows_.try_emplace(row, Range{row, k, k + 1});
        if (!added) at->second.end = k + 1;
    }
}

template <int D>
const typename SparseCellList<D>::Range* SparseCellList<D>::rowAt(const std::array<long, D>& c, const std::array<long, D>& offset) const {
    std::uint64_t row = 0;
    for (int d = D - 1; d >= 1; --d) {
        const auto dd = static_cast<std::size_t>(d);
        const long cd = c[dd] + offset[dd];
        if (cd < 0 || cd >= dims_[dd]) return nullptr;
        row = row * static_cast<std::uint64_t>(dims_[dd]) + static_cast<std::uint64_t>(cd);
    }
    const auto found = rows_.find(row);
    return found == rows_.end() ? nullptr : &found->second;
}

template <int D>
std::uint32_t SparseCellList<D>::firstPlaceFrom(const Range& row, std::uint64_t first) const {
    const auto begin = sortedCell_.begin() + row.begin, end = sortedCell_.begin() + row.end;
    return static_cast<std::uint32_t>(std::lower_bound(begin, end, first) - sortedCell_.begin());
}

template class SparseCellList<1>;
template class SparseCellList<2>;
template class SparseCellList<3>;

}  // namespace sph
