// ctest-labels: foam injection
// The injection model `patch` (OpenFOAM's patchInjection) on a mesh written by OpenFOAM (the
// skewed box of tests/foam/data/boxAscii) in a uniform stream U = (1 0 0) m/s: every particle
// starts in a cell behind a face of the patch, at the gas velocity's part normal to that face,
// (U·n) n, or at the given velocity; their mean position is the patch's area centroid (within
// five standard errors). A whole run conserves them; bad patches are one error at their key.
#include "../support/case_runs.h"
#include "../support/test_scenes.h"
#include "slides/config/scene_reader.h"
#include "slides/integrate/injector.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace slides {
namespace {

namespace fs = std::filesystem;

/// The box in U = (1 0 0) m/s with one injector `inlet` whose patchCoeffs are `coeffs`.
void writeBoxCase(const fs::path& directory, const std::string& injector) {
    fs::create_directories(directory / "0");
    fs::copy(fs::path(SLIDES_SOURCE_DIR) / "tests/foam/data/boxAscii/constant",
             directory / "constant", fs::copy_options::recursive);
    std::ofstream(directory / "0" / "U")
        << "FoamFile { version 2.0; format ascii; class volVectorField; object U; }\n"
           "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (1 0 0);\n"
           "boundaryField\n{\n    inlet { type fixedValue; value uniform (1 0 0); }\n"
           "    outlet { type zeroGradient; }\n    walls { type noSlip; }\n"
           "    sides { type symmetry; }\n}\n";
    std::ofstream(directory / "constant" / "slidesProperties")
        << "FoamFile { version 2.0; format ascii; class dictionary; object slidesProperties; }\n"
           "fluid { density 1.1; kinematicViscosity 25e-6; }\n"
           "carrier { type foamField; foamFieldCoeffs { interpolation cell; } }\n"
           "particles { density 1000; radiusDistribution { type fixed; value 5e-6; } }\n"
           "injectors { inlet { "
        << injector
        << " } }\n"
           "physics { gravity (0 0 0); }\n"
           "surfaces { target { type plane; point (10 0 0); normal (-1 0 0); } }\n"
           "time { dt 1e-3; endTime 0.5; }\n"
           "output { interval 0.1; }\n";
}

struct Injected {
    ParticleCloud cloud;
    std::vector<PatchTriangle> inlet;
};

Injected inject(const std::string& injector) {
    const test::ScratchDirectory scratch("patchInjection");
    writeBoxCase(scratch.path, injector);
    const Scene scene = readScene(scratch.path);
    const auto carrier = test::carrierOf(scene);
    Injector source(scene.injectors.at(0));
    Injected result;
    source.injectUntil(1e-12, 0.0, *carrier, result.cloud);
    result.inlet = carrier->patchTriangles("inlet");
    return result;
}

TEST(PatchInjection, StartsBehindThePatchAtTheNormalGasVelocityUniformInArea) {
    const auto [cloud, inlet] =
        inject("model patch; patchCoeffs { patch inlet; } count 4000; mode allAtStart;");
    ASSERT_EQ(cloud.size(), 4000u);
    ASSERT_EQ(cloud.carrierLocation.size(), cloud.size());
    const Vec3 gas(1, 0, 0);
    Vec3 centroid = Vec3::Zero();
    double area = 0;
    for (const PatchTriangle& t : inlet) {
        const double a = 0.5 * (t[1] - t[0]).cross(t[2] - t[0]).norm();
        centroid += a * (t[0] + t[1] + t[2]) / 3;
        area += a;
    }
    centroid /= area;
    Vec3 mean = Vec3::Zero(), squares = Vec3::Zero();
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        EXPECT_GE(cloud.carrierLocation[i], 0) << "particle " << i << " found in no cell";
        // (U·n) n for the normal of one of the patch's triangles.
        double closest = INFINITY;
        for (const PatchTriangle& t : inlet) {
            const Vec3 n = (t[1] - t[0]).cross(t[2] - t[0]).normalized();
            closest = std::min(closest, (cloud.velocity[i] - gas.dot(n) * n).norm());
        }
        EXPECT_LT(closest, 1e-12) << "particle " << i;
        mean += cloud.position[i];
        squares += cloud.position[i].cwiseProduct(cloud.position[i]);
    }
    const double n = static_cast<double>(cloud.size());
    mean /= n;
    const Vec3 standardError =
        ((squares / n - mean.cwiseProduct(mean)) / n).cwiseMax(0.0).cwiseSqrt();
    for (int axis = 0; axis < 3; ++axis)
        EXPECT_NEAR(mean[axis], centroid[axis], 5 * standardError[axis] + 1e-12) << axis;
}

TEST(PatchInjection, AGivenVelocityIsEveryParticles) {
    const auto [cloud, inlet] = inject(
        "model patch; patchCoeffs { patch inlet; velocity (2 0.5 0); } count 500; rate 1e6;");
    ASSERT_EQ(cloud.size(), 1u); // the first of one every microsecond
    EXPECT_EQ(cloud.velocity[0], Vec3(2, 0.5, 0));
}

TEST(PatchInjection, ARunCountsEveryParticleItInjects) {
    const test::ScratchDirectory scratch("patchInjectionRun");
    writeBoxCase(scratch.path, "model patch; patchCoeffs { patch inlet; } count 300; rate 3e4;");
    ASSERT_EQ(test::runCli(scratch.path.string() + " --quiet", scratch.path / "log"), 0)
        << test::slurp(scratch.path / "log");
    const auto summary =
        nlohmann::json::parse(test::slurp(scratch.path / "slides" / "summary.json"));
    const auto& particles = summary["particles"];
    EXPECT_EQ(particles["injected"].get<long>(), 300);
    // Carried at 1 m/s through the 0.1 m box in 0.5 s: all leave, most through the outlet (258
    // measured: the skewed box's sides and walls slant across the stream).
    long escaped = 0;
    for (const auto& [exit, count] : particles["escapedThrough"].items())
        escaped += count.get<long>();
    EXPECT_EQ(escaped, 300) << particles.dump();
    EXPECT_GT(particles["escapedThrough"]["outlet"].get<long>(), 240) << particles.dump();
}

TEST(PatchInjection, ABadPatchIsOneErrorAtItsKey) {
    const std::pair<const char*, const char*> cases[] = {
        {"model patch; patchCoeffs { patch roof; } count 10; rate 1e3;",
         "injectors.inlet.patchCoeffs.patch': no patch 'roof' in constant/polyMesh/boundary"},
        {"model patch; count 10; rate 1e3;", "injectors.inlet.patchCoeffs': missing key"},
        {"model disc; patchCoeffs { patch inlet; } count 10; rate 1e3;",
         "injectors.inlet.patchCoeffs': only model patch takes patchCoeffs"},
    };
    for (const auto& [injector, message] : cases) {
        const test::ScratchDirectory scratch("patchInjectionRefused");
        writeBoxCase(scratch.path, injector);
        EXPECT_EQ(test::runCli(scratch.path.string() + " --quiet", scratch.path / "log"), 2)
            << injector;
        EXPECT_NE(test::slurp(scratch.path / "log").find(message), std::string::npos)
            << test::slurp(scratch.path / "log");
        EXPECT_FALSE(fs::exists(scratch.path / "slides")) << injector;
    }
}

} // namespace
} // namespace slides
