// ctest-labels: deposition collision
// Wall patches as surfaces (surfaces/patch_wall.h): a sphere swept along a chord meets a face
// of the patch where its centre's gap to the face's plane falls to R while the centre lies over
// the face, exactly as on a plane (surfaces/plane_contact.h, d₀/(d₀ − d₁)); the first face met
// wins, also among faces of different sizes; faces seen from behind are not met; the mean plane
// is the area-weighted one.
#include "slides/surfaces/patch_wall.h"
#include "slides/surfaces/plane_contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace slides {
namespace {

const auto always = [](double, const Vec3&) { return true; };

/// A quadrilateral mesh face fanned about its centre into four triangles, appended to
/// triangles; corners counter-clockwise seen from the gas.
void addFace(std::vector<PatchTriangle>& triangles, const std::array<Vec3, 4>& corners) {
    const Vec3 middle = (corners[0] + corners[1] + corners[2] + corners[3]) / 4;
    for (std::size_t k = 0; k < 4; ++k)
        triangles.push_back({middle, corners[k], corners[(k + 1) % 4]});
}

/// The square [0, 1]² of the plane z = 0, the gas above: one face, or graded as a mesh is
/// (two faces of ½ on the left, 4 × 8 of ⅛ on the right: triangles of three size classes).
std::vector<PatchTriangle> floorSquare(bool graded = false) {
    std::vector<PatchTriangle> triangles;
    const auto square = [&](double x, double y, double side) {
        addFace(triangles, {Vec3(x, y, 0), Vec3(x + side, y, 0), Vec3(x + side, y + side, 0),
                            Vec3(x, y + side, 0)});
    };
    if (!graded) {
        square(0, 0, 1);
        return triangles;
    }
    square(0, 0, 0.5);
    square(0, 0.5, 0.5);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 8; ++j) square(0.5 + i / 8.0, j / 8.0, 1 / 8.0);
    return triangles;
}

class FlatPatch : public ::testing::TestWithParam<bool> {};

TEST_P(FlatPatch, IsMetAsItsPlane) {
    const PatchWall wall(floorSquare(GetParam()));
    const Surface plane{"floor", Vec3::Zero(), Vec3::UnitZ(), {}, SurfaceInteraction::absorb, "",
                        {}};
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> unit(0, 1);
    int met = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const double radius = 0.05 * unit(random);
        const Vec3 start(1.4 * unit(random) - 0.2, 1.4 * unit(random) - 0.2, 0.3 * unit(random));
        const Vec3 end =
            start + Vec3(0.4 * unit(random) - 0.2, 0.4 * unit(random) - 0.2, -0.6 * unit(random));
        const auto expected = planeContactFraction(plane, start, end, radius);
        const auto touch = wall.firstTouch(start, end, radius, always);
        // Where the plane is touched over the square, the patch is touched there too.
        const bool over = expected && [&] {
            const Vec3 centre = start + *expected * (end - start);
            return centre.x() >= 0 && centre.x() <= 1 && centre.y() >= 0 && centre.y() <= 1;
        }();
        ASSERT_EQ(touch.has_value(), over) << "trial " << trial;
        if (!over) continue;
        ++met;
        EXPECT_NEAR(touch->fraction, *expected, 1e-14);
        EXPECT_NEAR((touch->normal - Vec3::UnitZ()).norm(), 0, 1e-15);
        EXPECT_NEAR(touch->point.z(), 0, 1e-15);
    }
    EXPECT_GT(met, 300); // enough of the chords reach the square
}

INSTANTIATE_TEST_SUITE_P(Faces, FlatPatch, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "graded" : "oneFace"; });

TEST(PatchWall, FacesAreNotMetFromBehindNorWhenTheCallerRefuses) {
    const PatchWall wall(floorSquare());
    // From below the floor, moving up through it: the gas is above.
    EXPECT_FALSE(wall.firstTouch(Vec3(0.5, 0.5, -0.2), Vec3(0.5, 0.5, 0.2), 0.01, always));
    // In contact through the step (heights 0.015 and 0.018 < R) and moving away: touched at 0
    // as on a plane, which the caller
    // (the surface impacts' approach test) may refuse.
    const auto touching =
        wall.firstTouch(Vec3(0.5, 0.5, 0.015), Vec3(0.5, 0.5, 0.018), 0.02, always);
    ASSERT_TRUE(touching);
    EXPECT_EQ(touching->fraction, 0.0);
    EXPECT_FALSE(wall.firstTouch(Vec3(0.5, 0.5, 0.015), Vec3(0.5, 0.5, 0.018), 0.02,
                                 [](double, const Vec3& n) { return n.z() < 0; }));
}

TEST(PatchWall, InAConcaveCornerTheFirstFaceMetWins) {
    // Floor z = 0 (x, y in [0, 1]) and a wall x = 1 facing −x (y in [0, 1], z in [0, 1]).
    std::vector<PatchTriangle> triangles = floorSquare();
    addFace(triangles, {Vec3(1, 0, 0), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(1, 1, 0)});
    const PatchWall wall(triangles);
    const double radius = 0.1;
    // From (0.5, 0.5, 0.5) towards (1.3, 0.5, 0.1): the wall gap 0.4 − 0.8 s and the floor gap
    // 0.4 − 0.4 s reach 0 at s = 0.5 and 1: the wall first.
    const auto touch = wall.firstTouch(Vec3(0.5, 0.5, 0.5), Vec3(1.3, 0.5, 0.1), radius, always);
    ASSERT_TRUE(touch);
    EXPECT_NEAR(touch->fraction, 0.5, 1e-15);
    EXPECT_NEAR((touch->normal + Vec3::UnitX()).norm(), 0, 1e-15);
    // Steeper, towards (0.9, 0.5, −0.3): floor at s = 0.5, wall (gap 0.4 − 0.4 s) at s = 1.
    const auto floor = wall.firstTouch(Vec3(0.5, 0.5, 0.5), Vec3(0.9, 0.5, -0.3), radius, always);
    ASSERT_TRUE(floor);
    EXPECT_NEAR(floor->fraction, 0.5, 1e-15);
    EXPECT_NEAR((floor->normal - Vec3::UnitZ()).norm(), 0, 1e-15);
}

TEST(PatchWall, MeanPlaneIsAreaWeighted) {
    // The floor square (area 1, normal +z) and a wall of 2 × 1 facing −x at x = 1, z in [0, 2]:
    // mean normal ∝ (−2, 0, 1), centroid = (1·(0.5, 0.5, 0) + 2·(1, 0.5, 1))/3.
    std::vector<PatchTriangle> triangles = floorSquare();
    addFace(triangles, {Vec3(1, 0, 0), Vec3(1, 0, 2), Vec3(1, 1, 2), Vec3(1, 1, 0)});
    const PatchWall wall(triangles);
    EXPECT_NEAR((wall.meanNormal() - Vec3(-2, 0, 1).normalized()).norm(), 0, 1e-15);
    EXPECT_NEAR((wall.centroid() - Vec3(2.5, 1.5, 2) / 3).norm(), 0, 1e-15);
    EXPECT_EQ(wall.size(), 8u);
}

} // namespace
} // namespace slides
