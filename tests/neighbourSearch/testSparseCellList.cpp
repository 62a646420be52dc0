#include "neighbourSearch/SparseCellList.hpp"

#include "neighbourSearch/CellLinkedList.hpp"

#include <gtest/gtest.h>

#include <random>
#include <tuple>
#include <vector>

namespace {

// Every neighbour of every query, in the order the list visits them.
template <int D, class List>
std::vector<std::tuple<std::size_t, std::uint32_t, double>> visits(const List& list, const std::vector<sph::Vec<D>>& queries, double radius) {
    std::vector<std::tuple<std::size_t, std::uint32_t, double>> out;
    for (std::size_t q = 0; q < queries.size(); ++q)
        list.forEachNeighbour(queries[q], radius, [&](std::uint32_t j, const sph::Vec<D>& r, double r2) {
            EXPECT_EQ(r2, r.squaredNorm());
            out.emplace_back(q, j, r2);
        });
    return out;
}

// Points on a lattice of spacing dx (so that many lie on cell faces, where a rounding would
// file them in another cell), jittered ones, points outside the grid (clamped to its edge
// cells) and points listed twice; queried from all of them and from random places.
template <int D>
void visitsAsCellLinkedList(double dx) {
    std::mt19937 random(11 + D);
    std::uniform_real_distribution<double> coordinate(-0.1, 1.1), jitter(-0.3 * dx, 0.3 * dx);
    std::vector<sph::Vec<D>> points;
    const int across = static_cast<int>(1.0 / dx);
    for (int i = 0; i < across; i += 3) {
        sph::Vec<D> x = sph::Vec<D>::Constant(0.5 * dx + i * dx);
        x[0] = i * dx;
        points.push_back(x);
        for (int d = 0; d < D; ++d) x[d] += jitter(random);
        points.push_back(x);
    }
    for (int k = 0; k < 400; ++k) {
        sph::Vec<D> x;
        for (int d = 0; d < D; ++d) x[d] = coordinate(random);
        points.push_back(x);
        if (k % 50 == 0) points.push_back(x);  // two at one place: both reported, in index order
    }
    std::vector<sph::Vec<D>> queries = points;
    for (int k = 0; k < 400; ++k) {
        sph::Vec<D> x;
        for (int d = 0; d < D; ++d) x[d] = coordinate(random);
        queries.push_back(x);
    }
    const double radius = 3.0 * dx;
    const sph::Vec<D> lower = sph::Vec<D>::Zero(), upper = sph::Vec<D>::Ones();
    sph::CellLinkedList<D> dense(lower, upper, radius);
    dense.build(points);
    sph::SparseCellList<D> sparse(lower, upper, radius);
    sparse.build(points);
    const auto expected = visits<D>(dense, queries, radius);
    EXPECT_GT(expected.size(), 2 * queries.size());  // not vacuous
    EXPECT_EQ(visits<D>(sparse, queries, radius), expected);
}

}  // namespace

TEST(SparseCellList, VisitsTheNeighboursInCellLinkedListsOrder1D) { visitsAsCellLinkedList<1>(0.01); }
TEST(SparseCellList, VisitsTheNeighboursInCellLinkedListsOrder2D) { visitsAsCellLinkedList<2>(0.02); }
TEST(SparseCellList, VisitsTheNeighboursInCellLinkedListsOrder3D) { visitsAsCellLinkedList<3>(0.05); }

TEST(SparseCellList, ABuildReplacesThePointsOfTheLast) {
    sph::SparseCellList<2> cells(sph::Vec<2>::Zero(), sph::Vec<2>::Ones(), 0.1);
    cells.build({{0.5, 0.5}, {0.52, 0.5}});
    cells.build({{0.1, 0.1}});
    int near = 0, far = 0;
    cells.forEachNeighbour(sph::Vec<2>(0.5, 0.5), 0.1, [&](std::uint32_t, const sph::Vec<2>&, double) { ++near; });
    cells.forEachNeighbour(sph::Vec<2>(0.12, 0.1), 0.1, [&](std::uint32_t j, const sph::Vec<2>&, double) { far += j == 0; });
    EXPECT_EQ(near, 0);
    EXPECT_EQ(far, 1);
}
