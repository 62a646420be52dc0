#include "neighbourSearch/CellLinkedList.hpp"

#include "support/RestoreThreadCount.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <string>

namespace {

template <int D>
void compareWithBruteForce(int n, double radius) {
    std::mt19937 random(42 + D);
    std::uniform_real_distribution<double> coordinate(0.0, 1.0);
    std::vector<sph::Vec<D>> points(static_cast<std::size_t>(n));
    for (auto& p : points)
        for (int d = 0; d < D; ++d) p[d] = coordinate(random);
    sph::CellLinkedList<D> cells(sph::Vec<D>::Zero(), sph::Vec<D>::Ones(), radius);
    cells.build(points);
    std::size_t pairs = 0;
    for (const auto& x : points) {
        std::vector<std::uint32_t> found, expected;
        cells.forEachNeighbour(x, radius, [&](std::uint32_t j, const sph::Vec<D>& r, double r2) {
            found.push_back(j);
            EXPECT_NEAR(r2, r.squaredNorm(), 1e-15);
            EXPECT_LT((x - points[j] - r).norm(), 1e-15);
        });
        for (std::uint32_t j = 0; j < points.size(); ++j)
            if ((x - points[j]).squaredNorm() < radius * radius) expected.push_back(j);
        std::sort(found.begin(), found.end());
        ASSERT_EQ(found, expected);
        pairs += found.size();
    }
    EXPECT_GT(pairs, points.size());  // the test is not vacuous
}

}  // namespace

TEST(CellLinkedList, MatchesBruteForce1D) { compareWithBruteForce<1>(500, 0.013); }
TEST(CellLinkedList, MatchesBruteForce2D) { compareWithBruteForce<2>(2000, 0.05); }
TEST(CellLinkedList, MatchesBruteForce3D) { compareWithBruteForce<3>(3000, 0.11); }

TEST(CellLinkedList, PointsOutsideTheGridAreStillFound) {
    std::vector<sph::Vec<2>> points{{-0.05, 0.5}, {1.02, 0.5}, {0.01, 0.5}};
    sph::CellLinkedList<2> cells(sph::Vec<2>::Zero(), sph::Vec<2>::Ones(), 0.1);
    cells.build(points);
    int count = 0;
    cells.forEachNeighbour(sph::Vec<2>(0.0, 0.5), 0.1, [&](std::uint32_t, const sph::Vec<2>&, double) { ++count; });
    EXPECT_EQ(count, 2);
}

TEST(CellLinkedList, CellOrderIsAPermutationGroupedByCell) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(0.0, 1.0);
    std::vector<sph::Vec<2>> points(1000);
    for (auto& p : points) p = {coordinate(random), coordinate(random)};
    sph::CellLinkedList<2> cells(sph::Vec<2>::Zero(), sph::Vec<2>::Ones(), 0.1);
    const auto order = cells.cellOrder(points);
    std::vector<std::uint32_t> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    for (std::uint32_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i);
    // Cells half the search radius wide: 20 x 20.
    const auto cellOf = [](const sph::Vec<2>& p) { return static_cast<int>(p.y() * 20) * 20 + static_cast<int>(p.x() * 20); };
    for (std::size_t k = 1; k < order.size(); ++k) EXPECT_LE(cellOf(points[order[k - 1]]), cellOf(points[order[k]]));
}

TEST(CellLinkedList, OrderIsTheStableSortsWhateverTheNumberOfThreads) {
    // Crowded cells beside empty ones, and only points [100, 1950) listed (in no cell order: most
    // of a thread's block are strays in other threads' cells); built twice, the second time with
    // the points moved, so that the threads' ranges of cells come from the first build's places.
    std::mt19937 random(11);
    std::normal_distribution<double> coordinate(0.3, 0.1);
    std::vector<sph::Vec<2>> points(2000);
    for (auto& p : points) p = {std::clamp(coordinate(random), 0.0, 0.999), std::clamp(coordinate(random), 0.0, 0.999)};
    std::vector<sph::Vec<2>> moved = points;
    for (auto& p : moved) p = {std::clamp(p.x() + 0.2 * p.y(), 0.0, 0.999), std::clamp(0.999 - p.y() * p.y(), 0.0, 0.999)};
    const std::size_t begin = 100, end = 1950;
    const auto cellOf = [](const sph::Vec<2>& p) { return static_cast<std::uint32_t>(p.y() * 20) * 20 + static_cast<std::uint32_t>(p.x() * 20); };
    const auto expectStableSort = [&](const sph::CellLinkedList<2>& cells, const std::vector<sph::Vec<2>>& at, const std::string& where) {
        std::vector<std::uint32_t> expected(end - begin);
        std::iota(expected.begin(), expected.end(), static_cast<std::uint32_t>(begin));
        std::stable_sort(expected.begin(), expected.end(), [&](std::uint32_t i, std::uint32_t j) { return cellOf(at[i]) < cellOf(at[j]); });
        ASSERT_EQ(cells.pointCount(), expected.size());
        for (std::size_t k = 0; k < expected.size(); ++k) {
            ASSERT_EQ(cells.sortedIndex(k), expected[k]) << where << ", place " << k;
            ASSERT_EQ(cells.cellAt(k), cellOf(at[expected[k]]));
            ASSERT_EQ(cells.sortedPosition(k), at[expected[k]]);
        }
        // The cells' starts: a point's stencil finds exactly the listed points within the radius.
        for (const sph::Vec<2>& x : {at[begin], at[end - 1]}) {
            std::size_t found = 0, within = 0;
            cells.forEachNeighbour(x, 0.1, [&](std::uint32_t j, const sph::Vec<2>&, double) {
                EXPECT_TRUE(j >= begin && j < end);
                ++found;
            });
            for (std::size_t j = begin; j < end; ++j) within += (at[j] - x).squaredNorm() < 0.01;
            EXPECT_EQ(found, within) << where;
            EXPECT_GT(within, 10u) << where;
        }
    };
    const sph::test::RestoreThreadCount restore;
    for (const int threads : {1, 2, 3, 7}) {
        omp_set_num_threads(threads);
        sph::CellLinkedList<2> cells(sph::Vec<2>::Zero(), sph::Vec<2>::Ones(), 0.1);
        cells.build(points, begin, end);
        expectStableSort(cells, points, std::to_string(threads) + " threads, first build");
        cells.build(moved, begin, end);
        expectStableSort(cells, moved, std::to_string(threads) + " threads, second build");
    }
}

TEST(CellLinkedList, PeriodicDirectionsFindNearestImages) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> coordinate(0.0, 1.0);
    std::vector<sph::Vec<2>> points(1500);
    for (auto& p : points) p = {coordinate(random), 0.5 * coordinate(random)};
    const double radius = 0.07;
    sph::CellLinkedList<2> cells(sph::Vec<2>(0, 0), sph::Vec<2>(1, 0.5), radius, {true, false});
    cells.build(points);
    std::size_t acrossTheSeam = 0;
    for (const auto& x : points) {
        std::vector<std::uint32_t> found, expected;
        cells.forEachNeighbour(x, radius, [&](std::uint32_t j, const sph::Vec<2>& r, double) {
            found.push_back(j);
            if (std::abs(r.x()) < std::abs(x.x() - points[j].x())) ++acrossTheSeam;
        });
        for (std::uint32_t j = 0; j < points.size(); ++j) {
            sph::Vec<2> r = x - points[j];
            r.x() -= std::round(r.x());  // period 1 in x
            if (r.squaredNorm() < radius * radius) expected.push_back(j);
        }
        std::sort(found.begin(), found.end());
        ASSERT_EQ(found, expected);
    }
    EXPECT_GT(acrossTheSeam, 0u);
}

TEST(CellLinkedList, PeriodicDirectionShorterThanTwoAndAHalfRadiiIsRejected) {
    EXPECT_THROW(sph::CellLinkedList<2>(sph::Vec<2>(0, 0), sph::Vec<2>(0.2, 1), 0.1, {true, false}), std::invalid_argument);
}

// A cell is marked near a point exactly when a query from it has a range to search, also
// across a periodic side and after a build that moved the points.
TEST(CellLinkedList, CellsNearPointsAreThoseWhoseStencilHasOne) {
    for (const bool periodicX : {false, true}) {
        sph::CellLinkedList<2> cells(sph::Vec<2>::Zero(), sph::Vec<2>::Ones(), 0.1, {periodicX, false});
        cells.markCellsNearPoints();
        std::vector<sph::Vec<2>> points{{0.99, 0.5}, {0.3, 0.02}, {0.31, 0.03}, {0.6, 0.97}};
        for (int build = 0; build < 2; ++build) {
            cells.build(points);
            int near = 0, far = 0;
            for (double x = 0.0125; x < 1.0; x += 0.025) {
                for (double y = 0.0125; y < 1.0; y += 0.025) {
                    const sph::Vec<2> query(x, y);
                    sph::CellLinkedList<2> probe(sph::Vec<2>::Zero(), sph::Vec<2>::Ones(), 0.1, {periodicX, false});
                    probe.build({query});  // its cell number: the grid is the same
                    const bool marked = cells.anyPointNear(probe.cellAt(0));
                    ASSERT_EQ(marked, cells.stencilRanges(query).count > 0)
                        << "(" << x << ", " << y << "), periodic " << periodicX << ", build " << build;
                    ASSERT_EQ(cells.anyPointNear(query), marked);  // by position: the cell it lies in
                    (marked ? near : far) += 1;
                }
            }
            EXPECT_GT(near, 0);
            EXPECT_GT(far, near);
            points = {{0.5, 0.5}, {0.02, 0.9}};  // the second build must clear the first's marks
        }
    }
}

// A list that does not keep the marks answers that any point may be near: callers then search.
TEST(CellLinkedList, ListWithoutTheMarksHasAnyPointNearEverywhere) {
    sph::CellLinkedList<2> cells(sph::Vec<2>::Zero(), sph::Vec<2>::Ones(), 0.1);
    cells.build({sph::Vec<2>(0.9, 0.9)});
    EXPECT_TRUE(cells.anyPointNear(sph::Vec<2>(0.05, 0.05)));
}

// The stencil restricted to some cells lists the full stencil's places in those cells, in the
// same order (the pair loop of a decomposed run relies on the order), periodic or not.
TEST(CellLinkedList, RestrictedStencilKeepsTheKeptCellsPlacesInOrder) {
    for (const bool periodicX : {false, true}) {
        std::mt19937 random(5);
        std::uniform_real_distribution<double> coordinate(0.0, 1.0);
        std::vector<sph::Vec<2>> points(3000);
        for (auto& p : points) p = {coordinate(random), coordinate(random)};
        sph::CellLinkedList<2> cells(sph::Vec<2>::Zero(), sph::Vec<2>::Ones(), 0.1, {periodicX, false});
        cells.build(points);
        std::vector<std::uint8_t> keep(cells.cellCount());
        for (std::size_t c = 0; c < keep.size(); ++c) keep[c] = (c * 7 + c / 5) % 3 != 0;  // runs of kept cells, and gaps
        const auto places = [](const sph::CellLinkedList<2>::StencilRanges& stencil) {
            std::vector<std::uint32_t> listed;
            for (const auto& range : stencil)
                for (std::uint32_t k = range.begin; k < range.end; ++k) listed.push_back(k);
            return listed;
        };
        std::size_t dropped = 0;
        for (std::size_t q = 0; q < points.size(); q += 37) {
            std::vector<std::uint32_t> expected;
            for (const std::uint32_t k : places(cells.stencilRanges(points[q])))
                if (keep[cells.cellAt(k)])
                    expected.push_back(k);
                else
                    ++dropped;
            ASSERT_EQ(places(cells.stencilRanges(points[q], keep)), expected) << "point " << q << ", periodic " << periodicX;
        }
        EXPECT_GT(dropped, 0u);
    }
}
