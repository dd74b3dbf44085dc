// ctest-labels: collision
// Broad phase (collide/cell_grid.h, Algorithm 4 of the reference): the cell grid finds exactly
// the pairs a brute-force O(N²) search finds, on a compact cloud and a short jet (one bucket per
// cell of the bounding box) and on a long thin jet (hashed buckets, where a dense grid over the
// bounding box would be mostly empty).
#include "slides/collide/cell_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
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
    bool dense; ///< the layout the grid should choose for 3000 points in 1 mm cells
};

class CellGridAgainstBruteForce : public ::testing::TestWithParam<GridCase> {};

TEST_P(CellGridAgainstBruteForce, FindsEveryCloserPairOnce) {
    const double cell = 1e-3;
    const auto points = randomPoints(3000, GetParam().extent, 7);
    CellGrid grid;
    grid.build(points, cell);
    EXPECT_EQ(grid.dense(), GetParam().dense);
    PairSet found, candidates;
    std::size_t visits = 0;
    grid.forEachPairInBuckets(0, grid.bucketCount(), [&](std::uint32_t i, std::uint32_t j) {
        ++visits;
        candidates.insert(std::minmax(i, j));
        if ((points[i] - points[j]).norm() < cell) found.insert(std::minmax(i, j));
    });
    const PairSet expected = pairsCloserThan(points, cell);
    EXPECT_GT(expected.size(), 100u); // the scene has contacts to find
    EXPECT_EQ(found, expected);
    // Each candidate pair visited once: no duplicate visits from shared buckets.
    EXPECT_EQ(candidates.size(), visits);
}

TEST_P(CellGridAgainstBruteForce, QueriesFindEveryPointWithinReach) {
    const auto points = randomPoints(2000, GetParam().extent, 11);
    const auto probes = randomPoints(200, GetParam().extent, 12);
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

INSTANTIATE_TEST_SUITE_P(Clouds, CellGridAgainstBruteForce,
                         ::testing::Values(GridCase{"compactBox", Vec3(0.01, 0.01, 0.01), true},
                                           GridCase{"shortJet", Vec3(0.3, 0.004, 0.004), true},
                                           GridCase{"longThinJet", Vec3(3.0, 0.004, 0.004), false}),
                         [](const auto& info) { return std::string(info.param.name); });

} // namespace
} // namespace slides
