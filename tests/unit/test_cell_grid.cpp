// ctest-labels: collision
// Broad phase (collide/cell_grid.h, Algorithm 4 of the reference): the cell grid finds exactly
// the pairs a brute-force O(N²) search finds, and every point within a query's reach, on a
// compact cloud, a short jet, a long thin jet (where a dense grid over the bounding box would be
// mostly empty) and a cloud with one far outlier (a box of some 10¹¹ cells, almost all empty).
#include "slides/collide/cell_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <stdexcept>
#include <utility>

namespace slides {
namespace {

using PairSet = std::set<std::pair<std::uint32_t, std::uint32_t>>;

std::vector<Vec3> randomPoints(std::size_t count, const Vec3& extent, unsigned seed) {
    std::mt19937_64 generator(seed);
    std::uniform_real_distribution<double> unit(-0.5, 0.5);
    std::vector<Vec3> points(count);
    for (auto& p : points)
        p = Vec3(unit(generator), unit(generator), unit(generator)).cwiseProduct(extent);
    return points;
}

PairSet pairsCloserThan(const std::vector<Vec3>& points, double distance) {
    PairSet pairs;
    for (std::uint32_t i = 0; i < points.size(); ++i)
        for (std::uint32_t j = i + 1; j < points.size(); ++j)
            if ((points[i] - points[j]).norm() < distance) pairs.insert({i, j});
    return pairs;
}

struct GridCase {
    const char* name;
    Vec3 extent;
    bool outlier = false; ///< one more point 7 m away along (1, −1, 1)
};

std::vector<Vec3> cloudOf(const GridCase& grid, std::size_t count, unsigned seed) {
    auto points = randomPoints(count, grid.extent, seed);
    if (grid.outlier)
        points.emplace_back(7 / std::sqrt(3.0), -7 / std::sqrt(3.0), 7 / std::sqrt(3.0));
    return points;
}

class CellGridAgainstBruteForce : public ::testing::TestWithParam<GridCase> {};

TEST_P(CellGridAgainstBruteForce, FindsEveryCloserPairOnce) {
    const double cell = 1e-3;
    const auto points = cloudOf(GetParam(), 3000, 7);
    CellGrid grid;
    grid.build(points, cell);
    PairSet found, candidates;
    std::size_t visits = 0;
    // In two blocks of cells, as the threads of collectPairs split them.
    const std::size_t half = grid.occupiedCellCount() / 2;
    const auto visit = [&](std::uint32_t i, std::uint32_t j) {
        ++visits;
        candidates.insert(std::minmax(i, j));
        if ((points[i] - points[j]).norm() < cell) found.insert(std::minmax(i, j));
    };
    grid.forEachPairInCells(0, half, visit);
    grid.forEachPairInCells(half, grid.occupiedCellCount(), visit);
    const PairSet expected = pairsCloserThan(points, cell);
    EXPECT_GT(expected.size(), 100u); // the scene has contacts to find
    EXPECT_EQ(found, expected);
    // Each candidate pair visited once.
    EXPECT_EQ(candidates.size(), visits);
}

TEST_P(CellGridAgainstBruteForce, QueriesFindEveryPointWithinReach) {
    const auto points = cloudOf(GetParam(), 2000, 11);
    auto probes = cloudOf(GetParam(), 200, 12);
    probes.emplace_back(40, 0, 0); // far outside the box
    probes.push_back(points.back());
    CellGrid grid;
    grid.build(points, 0.7e-3);
    for (const double reach : {0.5e-3, 2.3e-3}) {
        for (const Vec3& probe : probes) {
            std::set<std::uint32_t> found;
            grid.forEachPointWithin(probe, reach, [&](std::uint32_t j) {
                if ((points[j] - probe).norm() <= reach) found.insert(j);
            });
            std::set<std::uint32_t> expected;
            for (std::uint32_t j = 0; j < points.size(); ++j)
                if ((points[j] - probe).norm() <= reach) expected.insert(j);
            ASSERT_EQ(found, expected);
        }
    }
}

TEST(CellGrid, RefusesAPointThatIsNotFinite) {
    CellGrid grid;
    const std::vector<Vec3> points{Vec3::Zero(), Vec3(std::nan(""), 0, 0)};
    EXPECT_THROW(grid.build(points, 1e-3), std::domain_error);
}

TEST(CellGrid, EmptyAndSinglePointGridsOfferNoPairs) {
    CellGrid grid;
    for (const std::size_t count : {0u, 1u}) {
        grid.build(std::vector<Vec3>(count, Vec3(1, 2, 3)), 1e-3);
        std::size_t visits = 0;
        grid.forEachPairInCells(0, grid.occupiedCellCount(), [&](auto, auto) { ++visits; });
        grid.forEachPointWithin(Vec3(1, 2, 3), 1e-3, [&](auto) { ++visits; });
        EXPECT_EQ(visits, count); // the single point is found by the query, no pair
    }
}

INSTANTIATE_TEST_SUITE_P(Clouds, CellGridAgainstBruteForce,
                         ::testing::Values(GridCase{"compactBox", Vec3(0.01, 0.01, 0.01)},
                                           GridCase{"shortJet", Vec3(0.3, 0.004, 0.004)},
                                           GridCase{"longThinJet", Vec3(3.0, 0.004, 0.004)},
                                           GridCase{"farOutlier", Vec3(0.01, 0.01, 0.01), true}),
                         [](const auto& info) { return std::string(info.param.name); });

} // namespace
} // namespace slides
