// ctest-labels: injection
// The injection model `patch` draws points uniform in area over a patch's triangles
// (integrate/patch_sampler.h; Turk 1990): each triangle is hit in proportion to its area
// (binomial counts), and within a triangle the marginals are those of a uniform density,
// checked by the Kolmogorov–Smirnov statistic against its 1 % critical value 1.628/√n. On a
// wedge the patch stands for the surface it sweeps about the axis: a 5° wedge's inlet face
// sweeps a disc, whose points have r² uniform and a uniform azimuth; its outer face a cylinder,
// whose points lie at its radius, uniform along it. Every point lies in the sampler's bounds, the
// swept disc's.
#include "../support/kolmogorov_smirnov.h"
#include "slides/core/random.h"
#include "slides/integrate/patch_sampler.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

namespace slides {
namespace {

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
        ASSERT_TRUE(insideBox(sampler.bounds(), point.position)) << "draw " << id;
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
    using test::kolmogorovSmirnov;
    const auto critical = test::kolmogorovSmirnovCritical;
    EXPECT_LT(kolmogorovSmirnov(squareX, uniform), critical(squareX.size()));
    EXPECT_LT(kolmogorovSmirnov(squareY, uniform), critical(squareY.size()));
    EXPECT_LT(kolmogorovSmirnov(largeY, [](double y) { return y - y * y / 4; }),
              critical(largeY.size()));
    // And the statistic does notice a wrong distribution: y in the large triangle is not uniform.
    EXPECT_GT(kolmogorovSmirnov(largeY, [](double y) { return y / 2; }), critical(largeY.size()));
}

/// The faces of a 5° wedge about the x axis (as tests/foam/data/wedge): radius R = 0.05 m at
/// its sides, so c = R cos 2.5° from the axis on its centre plane z = 0, length 0.1 m.
constexpr double wedgeC = 0.04993, wedgeS = 0.00218, wedgeLength = 0.1;
const AxisymmetricFrame wedgeFrame{Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(),
                                   2 * std::atan(wedgeS / wedgeC)};

TEST(PatchSampler, OnAWedgeTheInletFaceSweepsAUniformDisc) {
    // Seen from the gas (x > 0).
    const PatchSampler sampler({{Vec3::Zero(), Vec3(0, wedgeC, -wedgeS), Vec3(0, wedgeC, wedgeS)}},
                               wedgeFrame);
    ASSERT_TRUE(sampler.swept());
    const double pi = std::numbers::pi;
    EXPECT_NEAR(sampler.area(), pi * wedgeC * wedgeC, 1e-12 * wedgeC * wedgeC);
    constexpr int draws = 50000;
    std::vector<double> squaredRadius, azimuth;
    for (int id = 0; id < draws; ++id) {
        RandomStream random(11, static_cast<std::uint64_t>(id), RandomPurpose::injection, 0);
        const double a = random.uniform(), b = random.uniform(), c = random.uniform();
        const PatchSampler::Point point = sampler.draw(a, b, c, random.uniform());
        ASSERT_TRUE(insideBox(sampler.bounds(), point.position)) << "draw " << id;
        ASSERT_GT(point.position.x(), 0); // in the gas
        ASSERT_LT(point.position.x(), 1e-10);
        ASSERT_NEAR((point.normal - Vec3::UnitX()).norm(), 0, 1e-15);
        const double y = point.position.y(), z = point.position.z();
        squaredRadius.push_back((y * y + z * z) / (wedgeC * wedgeC));
        azimuth.push_back(std::atan2(z, y) / (2 * pi) + 0.5);
        // The turn takes the centre plane's radial direction to the point's.
        ASSERT_NEAR((point.turn * Vec3::UnitY() - Vec3(0, y, z).normalized()).norm(), 0, 1e-9);
    }
    const auto uniform = [](double x) { return x; };
    const double critical = test::kolmogorovSmirnovCritical(draws);
    EXPECT_LT(test::kolmogorovSmirnov(squaredRadius, uniform), critical);
    EXPECT_LT(test::kolmogorovSmirnov(azimuth, uniform), critical);
    // Its bounds are the swept disc's: of radius R = √(c² + s²) (the face's corners), wider by
    // a hair (1e-9 √(2 area) = 1.5e-11 m) and the rounding margin (1e-12 R) at most.
    const double corner = std::hypot(wedgeC, wedgeS);
    for (int axis : {1, 2}) {
        EXPECT_NEAR(sampler.bounds().min[axis], -corner, 1e-10) << axis;
        EXPECT_NEAR(sampler.bounds().max[axis], corner, 1e-10) << axis;
    }
    EXPECT_NEAR(sampler.bounds().min.x(), 0, 1e-10);
    EXPECT_NEAR(sampler.bounds().max.x(), 0, 1e-10);
    // The wedge's own face, not swept, would give r uniform, not r²: the test tells them apart.
    EXPECT_GT(test::kolmogorovSmirnov(squaredRadius, [](double f) { return std::sqrt(f); }),
              critical);
}

TEST(PatchSampler, OnAWedgeTheOuterFaceSweepsAUniformCylinder) {
    // The face y ≈ c between the wedge's sides, seen from the gas (y < c).
    const Vec3 a(0, wedgeC, -wedgeS), b(wedgeLength, wedgeC, -wedgeS),
        c(wedgeLength, wedgeC, wedgeS), d(0, wedgeC, wedgeS);
    const PatchSampler sampler({{a, b, c}, {a, c, d}}, wedgeFrame);
    const double pi = std::numbers::pi;
    EXPECT_NEAR(sampler.area(), 2 * pi * wedgeC * wedgeLength, 1e-12 * wedgeC * wedgeLength);
    constexpr int draws = 50000;
    std::vector<double> along, azimuth;
    for (int id = 0; id < draws; ++id) {
        RandomStream random(12, static_cast<std::uint64_t>(id), RandomPurpose::injection, 0);
        const double u = random.uniform(), v = random.uniform(), w = random.uniform();
        const PatchSampler::Point point = sampler.draw(u, v, w, random.uniform());
        ASSERT_TRUE(insideBox(sampler.bounds(), point.position)) << "draw " << id;
        const Vec3 across(0, point.position.y(), point.position.z());
        // On the centre plane's profile, r = c (less the hair into the gas), whatever the point
        // of the face drawn (the face's corners are at R = 0.05 m).
        ASSERT_NEAR(across.norm(), wedgeC, 1e-9);
        ASSERT_LT(across.norm(), wedgeC);
        ASSERT_NEAR((point.normal + across.normalized()).norm(), 0, 1e-12); // towards the axis
        along.push_back(point.position.x() / wedgeLength);
        azimuth.push_back(std::atan2(across.z(), across.y()) / (2 * pi) + 0.5);
    }
    const auto uniform = [](double x) { return x; };
    const double critical = test::kolmogorovSmirnovCritical(draws);
    EXPECT_LT(test::kolmogorovSmirnov(along, uniform), critical);
    EXPECT_LT(test::kolmogorovSmirnov(azimuth, uniform), critical);
}

} // namespace
} // namespace slides
