// ctest-labels: injection
// The injection model `patch` draws points uniform in area over a patch's triangles
// (integrate/patch_sampler.h; Turk 1990): each triangle is hit in proportion to its area
// (binomial counts), and within a triangle the marginals are those of a uniform density,
// checked by the Kolmogorov–Smirnov statistic against its 1 % critical value 1.628/√n.
#include "slides/core/random.h"
#include "slides/integrate/patch_sampler.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace slides {
namespace {

/// sup |F_n − F| of the sample against the cumulative distribution F.
double kolmogorovSmirnov(std::vector<double> sample, const std::function<double(double)>& F) {
    std::sort(sample.begin(), sample.end());
    const auto n = static_cast<double>(sample.size());
    double largest = 0;
    for (std::size_t k = 0; k < sample.size(); ++k) {
        const double f = F(sample[k]);
        largest = std::max(
            {largest, (static_cast<double>(k) + 1) / n - f, f - static_cast<double>(k) / n});
    }
    return largest;
}

TEST(PatchSampler, PointsAreUniformInAreaOverThePatch) {
    // The unit square in z = 0 as two triangles seen from z > 0 (areas ½, ½), a degenerate
    // triangle (area 0: never drawn), and a triangle of area 2 in the plane x = 5 seen from x > 5.
    const std::vector<PatchTriangle> triangles = {
        {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0)},
        {Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)},
        {Vec3(3, 3, 3), Vec3(3, 3, 3), Vec3(4, 4, 4)},
        {Vec3(5, 0, 0), Vec3(5, 2, 0), Vec3(5, 0, 2)},
    };
    const PatchSampler sampler(triangles);
    EXPECT_NEAR(sampler.area(), 3.0, 1e-15);
    constexpr int draws = 100000;
    std::vector<double> squareX, squareY, largeY;
    for (int id = 0; id < draws; ++id) {
        RandomStream random(7, static_cast<std::uint64_t>(id), RandomPurpose::injection, 0);
        const double a = random.uniform(), b = random.uniform(), c = random.uniform();
        const PatchSampler::Point point = sampler.draw(a, b, c);
        if (point.position.x() < 2) {
            // Off the face by 1e-9 √(2 · area) along the normal into the gas (+z).
            ASSERT_NEAR(point.position.z(), 1e-9, 1e-15);
            ASSERT_NEAR((point.normal - Vec3(0, 0, 1)).norm(), 0, 1e-15);
            ASSERT_TRUE(point.position.x() >= 0 && point.position.x() <= 1);
            squareX.push_back(point.position.x());
            squareY.push_back(point.position.y());
        } else {
            ASSERT_NEAR(point.position.x(), 5 + 2e-9, 1e-15);
            ASSERT_NEAR((point.normal - Vec3(1, 0, 0)).norm(), 0, 1e-15);
            ASSERT_LE(point.position.y() + point.position.z(), 2 + 1e-12);
            largeY.push_back(point.position.y());
        }
    }
    // Share of the large triangle: 2/3, binomial standard deviation √(p(1 − p)/n) = 0.0015.
    const double share = static_cast<double>(largeY.size()) / draws;
    EXPECT_NEAR(share, 2.0 / 3.0, 5 * std::sqrt(2.0 / 9.0 / draws));
    // Marginals: uniform on the square; y in the triangle y, z ≥ 0, y + z ≤ 2 has the density
    // (2 − y)/2, so F(y) = y − y²/4.
    const auto uniform = [](double x) { return x; };
    const auto critical = [](std::size_t n) { return 1.628 / std::sqrt(static_cast<double>(n)); };
    EXPECT_LT(kolmogorovSmirnov(squareX, uniform), critical(squareX.size()));
    EXPECT_LT(kolmogorovSmirnov(squareY, uniform), critical(squareY.size()));
    EXPECT_LT(kolmogorovSmirnov(largeY, [](double y) { return y - y * y / 4; }),
              critical(largeY.size()));
    // And the statistic does notice a wrong distribution: y in the large triangle is not uniform.
    EXPECT_GT(kolmogorovSmirnov(largeY, [](double y) { return y / 2; }), critical(largeY.size()));
}

} // namespace
} // namespace slides
