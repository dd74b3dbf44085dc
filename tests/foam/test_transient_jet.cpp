// ctest-labels: transient carrier
// foam-cases: transientJet
// foamCases/transientJet as shipped: pimpleFoam's pulsed planar jet read as a time series
// (carrier/foam_series.h). Its levels hold OpenFOAM's sine inlet (0.orig/U): the slot halves blow
// U_s = 1.5 ± 0.45 sin 2πft m/s, f = 100 Hz, in opposite phase, to round-off (binary doubles).
// Inside the jet the series is each level's field at its time (the steady carrier of that one
// time directory, to round-off) and the chord between two levels 0.5 ms apart, with ∂U/∂t the
// chord's slope. The shipped slidesProperties runs as written.
#include "../support/case_runs.h"
#include "slides/carrier/foam_carrier.h"
#include "slides/carrier/foam_field.h"
#include "slides/carrier/foam_mesh.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace slides {
namespace {

namespace fs = std::filesystem;
using std::numbers::pi;

const fs::path solvedRun = fs::path(SLIDES_FOAM_RUNS_DIR) / "transientJet";
constexpr double seriesStart = 0.1, writeInterval = 5e-4;    // [s], system/controlDict, Allrun
constexpr double level = 1.5, pulse = 0.45, frequency = 100; // 0.orig/U: m/s, m/s, Hz

/// The slot inlet's U_x at OpenFOAM time T on the upper (sign +1) or lower (−1) half.
double slotVelocity(double foamTime, int sign) {
    return level + sign * pulse * std::sin(2 * pi * frequency * foamTime);
}

/// The name OpenFOAM gives the time directory of run time t of the series (timePrecision 6).
std::string levelName(double runTime) {
    char name[32];
    std::snprintf(name, sizeof name, "%.6g", seriesStart + runTime);
    return name;
}

TEST(TransientJet, LevelsHoldTheSineInlet) {
    const FoamMesh mesh = readFoamMesh(solvedRun);
    const std::array<std::string, 2> halves{"slotUpper", "slotLower"};
    double worst = 0;
    for (int n = 0; n <= 200; n += 10) {
        const double time = seriesStart + n * writeInterval;
        const auto velocity =
            readFoamVolField<Vec3>(solvedRun / levelName(n * writeInterval), "U", mesh);
        for (int half = 0; half < 2; ++half) {
            const auto patch =
                std::find_if(mesh.patches.begin(), mesh.patches.end(),
                             [&](const FoamPatch& p) { return p.name == halves[half]; });
            ASSERT_NE(patch, mesh.patches.end()) << halves[half];
            const auto& values =
                velocity.patchValues[static_cast<std::size_t>(patch - mesh.patches.begin())];
            ASSERT_EQ(values.size(), 4u) << "four 0.5 mm faces a half";
            for (const Vec3& value : values)
                worst = std::max(
                    worst, (value - Vec3(slotVelocity(time, half == 0 ? 1 : -1), 0, 0)).norm());
        }
    }
    EXPECT_LT(worst, 1e-12);
}

TEST(TransientJet, SeriesIsEachLevelAtItsTimeAndTheChordBetween) {
    const FoamCarrier series(
        solvedRun, {.series = FoamSeriesSettings{std::pair{seriesStart, 0.2}, std::nullopt}});
    ASSERT_EQ(series.series()->levelCount(), 201u);
    // In the shear layers 10 and 40 mm downstream of the slot, where the vortices pass.
    const std::array<Vec3, 2> points{Vec3(0.01, 2e-3, 0.5e-3), Vec3(0.04, -4e-3, 0.5e-3)};
    const auto levelVelocity = [&](int n) {
        FoamCarrierSettings settings;
        settings.time = levelName(n * writeInterval);
        const FoamCarrier level(solvedRun, settings);
        CarrierSample gas;
        level.sample(points, 0, {}, gas);
        return gas.velocity;
    };
    CarrierSample gas;
    double worst = 0, worstRate = 0, largestChange = 0;
    std::vector<Vec3> atEnd = levelVelocity(0);
    for (int n = 0; n < 20; ++n) { // one forcing period
        const std::vector<Vec3> atStart = atEnd;
        atEnd = levelVelocity(n + 1);
        for (int k = 0; k < 4; ++k) {
            const double t = (n + k / 4.0) * writeInterval;
            series.holdInterval(t, t);
            series.sample(points, t, {.timeDerivative = true}, gas);
            for (std::size_t i = 0; i < points.size(); ++i) {
                const Vec3 chord = atStart[i] + (atEnd[i] - atStart[i]) * (k / 4.0);
                const Vec3 slope = (atEnd[i] - atStart[i]) / writeInterval;
                worst = std::max(worst, (gas.velocity[i] - chord).norm());
                if (k > 0) // at a written time the slope of either side is the derivative
                    worstRate = std::max(worstRate, (gas.velocityTimeDerivative[i] - slope).norm());
                largestChange = std::max(largestChange, (atEnd[i] - atStart[i]).norm());
            }
        }
    }
    std::printf("series against its levels: max |ΔU| %.2e m/s, max |Δ∂U/∂t| %.2e m/s², "
                "largest change between levels %.3f m/s\n",
                worst, worstRate, largestChange);
    EXPECT_LT(worst, 1e-12);
    EXPECT_LT(worstRate, 1e-12 / writeInterval);
    EXPECT_GT(largestChange, 0.01) << "the gas there changes between levels";
}

TEST(TransientJet, ShippedDictionaryRunsAsWritten) {
    // 5 ms of the run: 3e5 particles/s injected, none reaches the outlet 80 mm away at ≤ 2 m/s.
    test::ScratchDirectory scratch("transientJet");
    test::copySolvedRun("transientJet", scratch.path);
    const fs::path log = scratch.path / "log";
    ASSERT_EQ(test::runCli(scratch.path.string() + " --quiet --threads 2 --end-time 5e-3", log), 0)
        << test::slurp(log);
    const auto summary =
        nlohmann::json::parse(test::slurp(scratch.path / "slides" / "summary.json"));
    EXPECT_NE(summary["carrier"].get<std::string>().find("series of 201 levels"), std::string::npos)
        << summary["carrier"];
    EXPECT_NEAR(summary["particles"]["injected"].get<double>(), 1500, 1);
    EXPECT_EQ(summary["particles"]["escaped"].get<long>(), 0);
}

} // namespace
} // namespace slides
