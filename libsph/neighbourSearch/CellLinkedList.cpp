#include "neighbourSearch/CellLinkedList.hpp"

#include "core/FatalError.hpp"
#include "core/MemoryBudget.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>
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

// A counting sort, in parallel by destination: each thread takes a range of cells, counts and
// places the points in it, and moves only those. A thread's range starts at the cell of the place
// where its block of the last build's places started (the loops over places give each thread one
// contiguous block), so it writes the cells' starts that it reads afterwards; at the first build,
// ranges of as many cells. Between the sorts of the storage by cell the points of a thread's
// block of storage lie mostly in its own cells: it reads only its block, and lists the strays
// (points of its block in another thread's cells) for their thread, which reads those lists
// instead of every point. The order is the serial sort's whatever the number of threads and the
// ranges (runs stay reproducible bit for bit), and no array per thread and cell is summed across
// threads (in 2D there are more cells than points). The counts become each cell's end, and placing
// the points backwards (the later blocks' strays, the own block, the earlier blocks' strays) takes
// every end down to its cell's start, in one array.
template <int D>
void CellLinkedList<D>::build(const std::vector<Vec<D>>& points, std::size_t begin, std::size_t end) {
    const std::size_t n = end - begin, cells = cellCount();
#pragma omp parallel
    {
        const auto team = static_cast<std::size_t>(omp_get_num_threads()), thread = static_cast<std::size_t>(omp_get_thread_num());
#pragma omp single
        {
            threadTotals_.resize(team);
            straysOfThread_.resize(team);
            strayCountOfThread_.resize(team);
            firstCellOfThread_.resize(team + 1);
            const std::size_t lastCount = sortedCell_.size();
            firstCellOfThread_[0] = 0;
            for (std::size_t t = 1; t < team; ++t) firstCellOfThread_[t] = lastCount > 0 ? sortedCell_[lastCount * t / team] : cells * t / team;
            firstCellOfThread_[team] = cells;
            cellOf_.resize(n);
            sorted_.resize(n);
            sortedPosition_.resize(n + readablePastEnd);
            std::fill(sortedPosition_.begin() + static_cast<std::ptrdiff_t>(n), sortedPosition_.end(), Vec<D>::Zero());
            sortedCell_.resize(n);
        }  // implicit barrier
        // Plain pointers: a store through a member's data would make the compiler reload the others.
        std::uint32_t* const cellOf = cellOf_.data();
        std::uint32_t* const cellStart = cellStart_.data();
        const std::size_t firstCell = firstCellOfThread_[thread], lastCell = firstCellOfThread_[thread + 1];
        const std::size_t firstPoint = n * thread / team, lastPoint = n * (thread + 1) / team;
        const auto inRange = [firstCell, lastCell](std::uint32_t c) { return c >= firstCell && c < lastCell; };
        std::fill(cellStart + firstCell, cellStart + lastCell, 0);
        // Apart from the count, so that it runs in vector lanes.
        for (std::size_t k = firstPoint; k < lastPoint; ++k) cellOf[k] = static_cast<std::uint32_t>(cellIndex(points[begin + k]));
        std::vector<std::uint32_t>& strays = straysOfThread_[thread];
        if (team > 1 && strays.size() < lastPoint - firstPoint) strays.resize(lastPoint - firstPoint);  // never shrunk: no zeroing each build
        std::uint32_t* const stray = strays.data();
        // The strays listed without a branch, and not at all by a lone thread, whose range holds
        // every cell. The counts are the lambda's own: through a reference, a store to a cell's
        // count (the same type) could change them, and they would live in memory.
        const auto countOwn = [cellOf, cellStart, stray, firstPoint, lastPoint, inRange](auto listStrays) {
            std::uint32_t own = 0;
            std::size_t strayCount = 0;
            for (std::size_t k = firstPoint; k < lastPoint; ++k) {
                const std::uint32_t c = cellOf[k];
                const bool inOwnRange = inRange(c);
                if (inOwnRange) {
                    ++cellStart[c];
                    ++own;
                }
                if constexpr (listStrays) {
                    stray[strayCount] = static_cast<std::uint32_t>(k);
                    strayCount += !inOwnRange;
                }
            }
            return std::pair(own, strayCount);
        };
        auto [total, strayCount] = team > 1 ? countOwn(std::true_type{}) : countOwn(std::false_type{});
        strayCountOfThread_[thread] = strayCount;
#pragma omp barrier
        for (std::size_t t = 0; t < team; ++t) {
            if (t == thread) continue;
            for (std::size_t s = 0; s < strayCountOfThread_[t]; ++s) {
                const std::uint32_t k = straysOfThread_[t][s];
                const std::uint32_t c = cellOf[k];
                if (inRange(c)) {
                    ++cellStart[c];
                    ++total;
                }
            }
        }
        threadTotals_[thread] = total;
#pragma omp barrier
        std::uint32_t cellEnd = 0;
        for (std::size_t t = 0; t < thread; ++t) cellEnd += threadTotals_[t];
        for (std::size_t c = firstCell; c < lastCell; ++c) {
            cellEnd += cellStart[c];
            cellStart[c] = cellEnd;
        }
        std::uint32_t* const sorted = sorted_.data();
        std::uint32_t* const sortedCell = sortedCell_.data();
        Vec<D>* const sortedPosition = sortedPosition_.data();
        const Vec<D>* const from = points.data() + begin;
        const auto place = [cellOf, cellStart, sorted, sortedCell, sortedPosition, from, begin, inRange](std::size_t k) {
            const std::uint32_t c = cellOf[k];
            if (!inRange(c)) return;
            const std::uint32_t at = --cellStart[c];
            sorted[at] = static_cast<std::uint32_t>(begin + k);
            sortedPosition[at] = from[k];
            sortedCell[at] = c;
        };
        const auto placeStraysOf = [&](std::size_t t) {
            for (std::size_t s = strayCountOfThread_[t]; s-- > 0;) place(straysOfThread_[t][s]);
        };
        for (std::size_t t = team; t-- > thread + 1;) placeStraysOf(t);
        for (std::size_t k = lastPoint; k-- > firstPoint;) place(k);
        for (std::size_t t = thread; t-- > 0;) placeStraysOf(t);
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
