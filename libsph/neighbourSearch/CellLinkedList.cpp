#include "neighbourSearch/CellLinkedList.hpp"

#include <cmath>
#include <stdexcept>

namespace sph {

template <int D>
CellLinkedList<D>::CellLinkedList(const Vec<D>& lower, const Vec<D>& upper, double cellSize, const std::array<bool, D>& periodic)
    : lower_(lower), extent_(upper - lower), cellSize_(cellSize), periodic_(periodic) {
    std::size_t cells = 1;
    for (int d = 0; d < D; ++d) {
        const auto dd = static_cast<std::size_t>(d);
        const double extent = extent_[d];
        if (!(extent > 0.0)) throw std::invalid_argument("cell-linked list: empty domain");
        int n = std::max(1, static_cast<int>(std::ceil(extent / cellSize)));
        if (periodic_[dd]) {
            n = static_cast<int>(std::floor(extent / cellSize));  // cells no smaller than cellSize, tiling the period
            if (n < 3) throw std::invalid_argument("cell-linked list: a periodic direction must be at least three support radii long");
            anyPeriodic_ = true;
        }
        dims_[dd] = n;
        inverseCellSizes_[d] = periodic_[dd] ? n / extent : 1.0 / cellSize;
        cells *= static_cast<std::size_t>(n);
    }
    cellStart_.assign(cells + 1, 0);
}

template <int D>
void CellLinkedList<D>::build(const std::vector<Vec<D>>& points, std::size_t begin, std::size_t end) {
    points_ = &points;
    const std::size_t n = end - begin;
    std::vector<std::uint32_t> cellOf(n);
    std::fill(cellStart_.begin(), cellStart_.end(), 0);
    for (std::size_t k = 0; k < n; ++k) {
        cellOf[k] = static_cast<std::uint32_t>(cellIndex(points[begin + k]));
        ++cellStart_[cellOf[k] + 1];
    }
    for (std::size_t c = 1; c < cellStart_.size(); ++c) cellStart_[c] += cellStart_[c - 1];
    sorted_.resize(n);
    std::vector<std::uint32_t> fill(cellStart_.begin(), cellStart_.end() - 1);
    for (std::size_t k = 0; k < n; ++k) sorted_[fill[cellOf[k]]++] = static_cast<std::uint32_t>(begin + k);
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
