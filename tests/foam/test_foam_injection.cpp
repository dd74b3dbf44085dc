// ctest-labels: foam run
// Injection into an OpenFOAM carrier: the cell the injector's search finds is kept in the cloud
// (CarrierField::sampleFrom), so the first step walks from it instead of searching again; on the
// 5° wedge OpenFOAM wrote (tests/foam/data/wedge) with a uniform stream, tracked in 3-D. And the
// cloud ordered by location (core/particle_order.h) every few steps: a run resumed from its state
// between two reorders goes on bit for bit as the uninterrupted one.
#include "../support/test_scenes.h"
#include "slides/carrier/foam_carrier.h"
#include "slides/config/scene_reader.h"
#include "slides/core/particle_order.h"
#include "slides/integrate/injector.h"
#include "slides/run/stepper.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace slides {
namespace {

const std::filesystem::path data = std::filesystem::path(SLIDES_SOURCE_DIR) / "tests/foam/data";

/// The wedge mesh with U = (4 0 0) m/s and a spray of `count` particles on a disc inside it.
std::filesystem::path wedgeStreamCase(int count) {
    const auto directory = std::filesystem::temp_directory_path() /
                           ("slides_foam_injection_" + std::to_string(::getpid()));
    std::filesystem::remove_all(directory);
    std::filesystem::create_directories(directory / "0");
    std::filesystem::copy(data / "wedge" / "constant", directory / "constant",
                          std::filesystem::copy_options::recursive);
    std::ofstream(directory / "0" / "U")
        << "FoamFile { version 2.0; format ascii; class volVectorField; object U; }\n"
           "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (4 0 0);\n"
           "boundaryField\n{\n    inlet { type fixedValue; value uniform (4 0 0); }\n"
           "    outlet { type zeroGradient; }\n    outer { type slip; value uniform (4 0 0); }\n"
           "    \"(front|back)\" { type wedge; }\n    axis { type empty; }\n}\n";
    std::ofstream(directory / "constant" / "slidesProperties")
        << "FoamFile { version 2.0; format ascii; class dictionary; object slidesProperties; }\n"
           "fluid { density 1.1; kinematicViscosity 25e-6; }\n"
           "nozzle { centre (0.01 0 0); axis (1 0 0); radius 0.01; }\n"
           "carrier { type foamField; }\n"
           "particles { count "
        << count
        << "; density 1000; radiusDistribution { type fixed; value 5e-6; } }\n"
           "injection { mode allAtStart; seed 3; }\n"
           "time { dt 1e-4; endTime 0.1; }\n"
           "surfaces { target { type plane; point (0.08 0 0); normal (-1 0 0); } }\n"
           "output { interval 0.01; }\n";
    return directory;
}

// Every injected particle carries the tetrahedron that holds it (the walk's start for its first
// step): its barycentric weights there are ≥ −tolerance; without it the cloud's locations would
// be empty or −1.
TEST(FoamInjection, KeepsTheTetrahedronItsSearchFound) {
    const auto directory = wedgeStreamCase(500);
    const Scene scene = readScene(directory);
    const auto carrier = test::carrierOf(scene);
    const auto& foam = dynamic_cast<const FoamCarrier&>(*carrier);
    Injector injector(scene.injection, scene.nozzle, scene.particles);
    ParticleCloud cloud;
    injector.injectUntil(1e-12, 0.0, *carrier, cloud);
    ASSERT_EQ(cloud.size(), 500u);
    ASSERT_EQ(cloud.carrierLocation.size(), cloud.size());
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        Mat3 rotation;
        const Vec3 onWedge = foam.wedge()->toWedge(cloud.position[i], rotation);
        ASSERT_GE(cloud.carrierLocation[i], 0) << "particle " << i;
        const TetLocation tet = foam.locator().tetAt(cloud.carrierLocation[i]);
        const auto weights =
            barycentricWeights(foam.locator().vertices(tet.cell, tet.face, tet.edge), onWedge);
        EXPECT_GE(*std::min_element(weights.begin(), weights.end()), -FoamLocator::tolerance)
            << "particle " << i;
        // The stream is uniform: each particle starts with its velocity (to round-off).
        EXPECT_NEAR((cloud.velocity[i] - Vec3(4, 0, 0)).norm(), 0.0, 1e-12);
    }
    std::filesystem::remove_all(directory);
}

// A run stopped after a step count between two reorders and resumed in a new stepper from its
// counters and cloud (what a checkpoint holds) reorders at the same steps as the uninterrupted
// run and ends with the same particles, positions and velocities, bit for bit. The cloud is
// reordered on the way: its ids are no longer in injection order.
TEST(ParticleOrder, ResumedRunReordersAtTheSameSteps) {
    const auto directory = wedgeStreamCase(300);
    Scene scene = readScene(directory);
    scene.physics.gravity = Vec3(0, -9.81, 0); // paths that differ from particle to particle
    const auto carrier = test::carrierOf(scene);
    scene.domain = carrier->bounds().value(); // as the command line sets it
    const long stopAt = 3 * particleOrderInterval + 2, endAt = 6 * particleOrderInterval + 1;
    Stepper uninterrupted(scene, *carrier);
    for (long n = 0; n < endAt; ++n) uninterrupted.step();
    Stepper first(scene, *carrier);
    for (long n = 0; n < stopAt; ++n) first.step();
    Stepper resumed(scene, *carrier);
    resumed.resume(first.counters(), first.cloud(), first.arrivals(), {});
    for (long n = stopAt; n < endAt; ++n) resumed.step();

    const ParticleCloud& expected = uninterrupted.cloud();
    const ParticleCloud& actual = resumed.cloud();
    ASSERT_GT(expected.size(), 100u)
        << uninterrupted.escaped() << " escaped, " << uninterrupted.arrivals().size()
        << " arrived, t = " << uninterrupted.time();
    EXPECT_FALSE(std::is_sorted(expected.id.begin(), expected.id.end()));
    EXPECT_EQ(actual.id, expected.id);
    EXPECT_EQ(actual.position, expected.position);
    EXPECT_EQ(actual.velocity, expected.velocity);
    EXPECT_EQ(actual.carrierLocation, expected.carrierLocation);
    std::filesystem::remove_all(directory);
}

} // namespace
} // namespace slides
