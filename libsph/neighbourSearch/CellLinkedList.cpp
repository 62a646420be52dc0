#include "neighbourSearch/CellLinkedList.hpp"

#include <cmath>
#include <stdexcept>

namespace sph {

template <int D>
CellLinkedList<D>::CellLinkedList(const Vec<D>& lower, const Vec<D>& upper, double radius, const std::array<bool, D>& periodic)
    : lower_(lower), extent_(upper - lower), periodic_(periodic) {
    const double cellSize = radius / reach;
    std::size_t cells = 1;
    for (int d = 0; d < D; ++d) {
        const auto dd = static_cast<std::size_t>(d);
        const double extent = extent_[d];
        if (!(extent > 0.0)) throw std::invalid_argument("cell-linked list: empty domain");
        int n = std::max(1, static_cast<int>(std::ceil(extent / cellSize)));
        if (periodic_[dd]) {
            n = static_cast<int>(std::floor(extent / cellSize));  // cells no smaller than cellSize, tiling the period
            if (n < 2 * reach + 1)  // else a query would meet a cell twice
                throw std::invalid_argument("cell-linked list: a periodic direction must be at least 2.5 support radii long");
            anyPeriodic_ = true;
            period_[dd] = extent;
            inversePeriod_[dd] = 1.0 / extent;
        }
        dims_[dd] = n;
        inverseCellSizes_[d] = periodic_[dd] ? n / extent : 1.0 / cellSize;
        cells *= static_cast<std::size_t>(n);
    }
    cellStart_.assign(cells + 1, 0);
}

template <int D>
void CellLinkedList<D>::build(const std::vector<Vec<D>>& points, std::size_t begin, std::size_t end) {
    const std::size_t n = end - begin;
    std::vector<std::uint32_t> cellOf(n);
    std::fill(cellStart_.begin(), cellStart_.end(), 0);
#pragma omp parallel for schedule(static)
    for (std::size_t k = 0; k < n; ++k) cellOf[k] = static_cast<std::uint32_t>(cellIndex(points[begin + k]));
    for (std::size_t k = 0; k < n; ++k) ++cellStart_[cellOf[k] + 1];
    for (std::size_t c = 1; c < cellStart_.size(); ++c) cellStart_[c] += cellStart_[c - 1];
    sorted_.resize(n);
    sortedPosition_.resize(n + readablePastEnd);
    std::fill(sortedPosition_.begin() + static_cast<std::ptrdiff_t>(n), sortedPosition_.end(), Vec<D>::Zero());
    sortedCell_.resize(n);
    std::vector<std::uint32_t> fill(cellStart_.begin(), cellStart_.end() - 1);
    for (std::size_t k = 0; k < n; ++k) {
        const std::uint32_t place = fill[cellOf[k]]++;
        sorted_[place] = static_cast<std::uint32_t>(begin + k);
        sortedPosition_[place] = points[begin + k];
        sortedCell_[place] = cellOf[k];
    }
}

template <int D>
typename CellLinkedList<D>::StencilRanges CellLinkedList<D>::stencilRanges(const Vec<D>& x) const {
    StencilRanges stencil;
    const auto add = [&](long first, long last) {
        const std::uint32_t begin = cellStart_[static_cast<std::size_t>(first)], end = cellStart_[static_cast<std::size_t>(last) + 1];
        if (begin < end) stencil.ranges[static_cast<std::size_t>(stencil.count++)] = {begin, end};
    };
    const std::array<int, D> c = cellCoordinates(x);
    std::array<int, D> offset{};
    for (int d = 1; d < D; ++d) offset[static_cast<std::size_t>(d)] = -reach;
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
                for (int dx = -reach; dx <= reach; ++dx) {
                    const long cell = rowCell * dims_[0] + (c[0] + dx + dims_[0]) % dims_[0];
                    add(cell, cell);
                }
            } else {
                add(rowCell * dims_[0] + std::max(c[0] - reach, 0), rowCell * dims_[0] + std::min(c[0] + reach, dims_[0] - 1));
            }
        }
        int d = 1;
        for (; d < D; ++d) {
            if (++offset[static_cast<std::size_t>(d)] <= reach) break;
            offset[static_cast<std::size_t>(d)] = -reach;
        }
        if (d >= D) break;
    }
    return stencil;
}

template <int D>
std::vector<std::uint32_t> CellLinkedList<D>::cellOrder(const std::vector<Vec<D>>& points) const {
    CellLinkedList<D> copy(*this);
    copy.build(points);
    return copy.sorted_;
}

template class CellLinkedList<1>;
template class CellLinkedList<2>;
template class CellLinkedList<3>;

}  // namespace sph
