#include "neighbourSearch/CellLinkedList.hpp"

#include "core/FatalError.hpp"
#include "core/MemoryBudget.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <cmath>
#include <stdexcept>
#include <utility>

namespace sph {

template <int D>
CellLinkedList<D>::CellLinkedList(const Vec<D>& lower, const Vec<D>& upper, double radius, const std::array<bool, D>& periodic)
    : lower_(lower), periodic_(periodic) {
    const double cellSize = radius / reach;
    // Cells are indexed by 32-bit integers and take 9 bytes each: a domain far larger than its
    // radius (a spacing typed 1000 times too small) is refused before anything is allocated.
    double cellCount = 1.0;
    for (int d = 0; d < D; ++d) cellCount *= std::max(1.0, std::ceil((upper[d] - lower[d]) / cellSize));
    if (!(cellCount < 4294967295.0))
        throw FatalError(
            fmt::format("error: the domain from ({:g}) to ({:g}) would need {:.3g} neighbour-search cells of size {:g} "
                        "(at most 4294967294): the spacing is too small for the domain, or the domain too large",
                        fmt::join(lower.data(), lower.data() + D, " "), fmt::join(upper.data(), upper.data() + D, " "), cellCount, cellSize));
    requireMemory(9.0 * cellCount, fmt::format("the neighbour search over the domain ({:.3g} cells of size {:g})", cellCount, cellSize));
    std::size_t cells = 1;
    for (int d = 0; d < D; ++d) {
        const auto dd = static_cast<std::size_t>(d);
        const double extent = upper[d] - lower[d];
        if (!(extent > 0.0)) throw std::invalid_argument("cell-linked list: empty domain");
        int n = std::max(1, static_cast<int>(std::ceil(extent / cellSize)));
        if (periodic_[dd]) {
            n = static_cast<int>(std::floor(extent / cellSize));  // cells no smaller than cellSize, tiling the period
            if (n < 2 * reach + 1)                                // else a query would meet a cell twice
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

namespace {

// The share [first, last) of `count` items that thread `thread` of `team` takes.
std::pair<std::size_t, std::size_t> shareOf(std::size_t count, int thread, int team) {
    const auto t = static_cast<std::size_t>(thread), threads = static_cast<std::size_t>(team);
    return {count * t / threads, count * (t + 1) / threads};
}

// Calls row(first, last) for the cells [first, last] of each row of the stencil around the cell
// at c: five consecutive cells, or one cell at a time across a periodic x boundary. A local
// function, called once per use, so that the compiler inlines it into the hot stencilRanges.
template <int D, class Row>
void forEachStencilRow(const std::array<int, D>& c, const std::array<int, D>& dims, const std::array<bool, D>& periodic, Row&& row) {
    constexpr int reach = CellLinkedList<D>::reach;
    std::array<int, D> offset{};
    for (int d = 1; d < D; ++d) offset[static_cast<std::size_t>(d)] = -reach;
    while (true) {
        bool inside = true;
        long rowCell = 0;
        for (int d = D - 1; d >= 1; --d) {
            const auto dd = static_cast<std::size_t>(d);
            int cd = c[dd] + offset[dd];
            if (periodic[dd]) cd = (cd + dims[dd]) % dims[dd];
            if (cd < 0 || cd >= dims[dd]) inside = false;
            rowCell = rowCell * dims[dd] + cd;
        }
        if (inside) {
            if (periodic[0]) {
                for (int dx = -reach; dx <= reach; ++dx) {
                    const long cell = rowCell * dims[0] + (c[0] + dx + dims[0]) % dims[0];
                    row(cell, cell);
                }
            } else {
                row(rowCell * dims[0] + std::max(c[0] - reach, 0), rowCell * dims[0] + std::min(c[0] + reach, dims[0] - 1));
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

}  // namespace

// A counting sort, in parallel by destination: each thread counts, then places, the points of
// its own range of cells, reading every point's cell (4 bytes) but moving only its own points.
// The order is the serial sort's whatever the number of threads (runs stay reproducible bit for
// bit), and no array per thread and cell is summed across threads (in 2D there are more cells
// than points).
template <int D>
void CellLinkedList<D>::build(const std::vector<Vec<D>>& points, std::size_t begin, std::size_t end) {
    const std::size_t n = end - begin, cells = cellCount();
    cellOf_.resize(n);
    nextPlace_.resize(cells);
    sorted_.resize(n);
    sortedPosition_.resize(n + readablePastEnd);
    std::fill(sortedPosition_.begin() + static_cast<std::ptrdiff_t>(n), sortedPosition_.end(), Vec<D>::Zero());
    sortedCell_.resize(n);
#pragma omp parallel
    {
        const int team = omp_get_num_threads(), thread = omp_get_thread_num();
#pragma omp single
        threadTotals_.resize(static_cast<std::size_t>(team));  // implicit barrier
#pragma omp for schedule(static)
        for (std::size_t k = 0; k < n; ++k) cellOf_[k] = static_cast<std::uint32_t>(cellIndex(points[begin + k]));
        // Each cell's count, then each range's starts from the earlier ranges' totals.
        const auto [firstCell, lastCell] = shareOf(cells, thread, team);
        std::fill(nextPlace_.begin() + static_cast<std::ptrdiff_t>(firstCell), nextPlace_.begin() + static_cast<std::ptrdiff_t>(lastCell), 0);
        std::uint32_t total = 0;
        for (std::size_t k = 0; k < n; ++k) {
            const std::uint32_t c = cellOf_[k];
            if (c >= firstCell && c < lastCell) {
                ++nextPlace_[c];
                ++total;
            }
        }
        threadTotals_[static_cast<std::size_t>(thread)] = total;
#pragma omp barrier
        std::uint32_t start = 0;
        for (int t = 0; t < thread; ++t) start += threadTotals_[static_cast<std::size_t>(t)];
        for (std::size_t c = firstCell; c < lastCell; ++c) {
            const std::uint32_t count = nextPlace_[c];
            cellStart_[c] = start;
            nextPlace_[c] = start;
            start += count;
        }
#pragma omp barrier
        // Placing splits the cells anew, by the places they fill, so that threads move as many points.
        const auto [firstPlace, lastPlace] = shareOf(n, thread, team);
        const auto cellsStartingBy = [&](std::size_t place) {
            return static_cast<std::size_t>(std::upper_bound(cellStart_.begin(), cellStart_.end() - 1, place) - cellStart_.begin());
        };
        const std::size_t placingFrom = thread == 0 ? 0 : cellsStartingBy(firstPlace);
        const std::size_t placingTo = thread == team - 1 ? cells : cellsStartingBy(lastPlace);
        // Plain pointers: a store through a member's data would make the compiler reload the others.
        const std::uint32_t* const cellOf = cellOf_.data();
        std::uint32_t* const nextPlace = nextPlace_.data();
        std::uint32_t* const sorted = sorted_.data();
        std::uint32_t* const sortedCell = sortedCell_.data();
        Vec<D>* const sortedPosition = sortedPosition_.data();
        const Vec<D>* const from = points.data() + begin;
        for (std::size_t k = 0; k < n; ++k) {
            const std::uint32_t c = cellOf[k];
            if (c >= placingFrom && c < placingTo) {
                const std::uint32_t place = nextPlace[c]++;
                sorted[place] = static_cast<std::uint32_t>(begin + k);
                sortedPosition[place] = from[k];
                sortedCell[place] = c;
            }
        }
    }
    cellStart_[cells] = static_cast<std::uint32_t>(n);
    if (!pointNear_.empty()) markCellsNear();
}

template <int D>
typename CellLinkedList<D>::StencilRanges CellLinkedList<D>::stencilRanges(const Vec<D>& x) const {
    StencilRanges stencil;
    forEachStencilRow<D>(cellCoordinates(x), dims_, periodic_, [&](long first, long last) {
        const std::uint32_t begin = cellStart_[static_cast<std::size_t>(first)], end = cellStart_[static_cast<std::size_t>(last) + 1];
        if (begin < end) stencil.ranges[static_cast<std::size_t>(stencil.count++)] = {begin, end};
    });
    return stencil;
}

template <int D>
typename CellLinkedList<D>::StencilRanges CellLinkedList<D>::stencilRanges(const Vec<D>& x, const std::vector<std::uint8_t>& keepCell) const {
    StencilRanges stencil;
    forEachStencilRow<D>(cellCoordinates(x), dims_, periodic_, [&](long first, long last) {
        for (long cell = first; cell <= last; ++cell) {
            if (!keepCell[static_cast<std::size_t>(cell)]) continue;
            long runEnd = cell;  // consecutive kept cells make one range
            while (runEnd < last && keepCell[static_cast<std::size_t>(runEnd + 1)]) ++runEnd;
            const std::uint32_t begin = cellStart_[static_cast<std::size_t>(cell)], end = cellStart_[static_cast<std::size_t>(runEnd) + 1];
            if (begin < end) stencil.ranges[static_cast<std::size_t>(stencil.count++)] = {begin, end};
            cell = runEnd;
        }
    });
    return stencil;
}

template <int D>
void CellLinkedList<D>::markCellsNearPoints() {
    pointNear_.assign(cellCount(), 0);
}

// A point lies in the stencil of exactly the cells of its own cell's stencil: each cell with
// points marks its stencil once (the places are in cell order), so that a wall list rebuilt
// every step (moving walls) pays per cell, not per point.
template <int D>
void CellLinkedList<D>::markCellsNear() {
    std::fill(pointNear_.begin(), pointNear_.end(), 0);
    for (std::size_t k = 0; k < sortedCell_.size(); ++k) {
        if (k > 0 && sortedCell_[k] == sortedCell_[k - 1]) continue;
        forEachStencilRow<D>(cellCoordinates(sortedPosition_[k]), dims_, periodic_,
                             [&](long first, long last) { std::fill(pointNear_.begin() + first, pointNear_.begin() + last + 1, 1); });
    }
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
