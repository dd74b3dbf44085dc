// ctest-labels: transient carrier
// OpenFOAM time series (carrier/foam_series.h, carrier/time_levels.h): the uniform oscillating
// gas u = U sin ωt of carrier/oscillating_gas.h written by this test as time directories on the
// 40-cell channel of tests/foam/data/channel3d. Uniform in space, so cellPoint is exact and
// every difference from the analytic carrier is the time interpolation's: U(t) linear between
// levels errs by at most U ω² Δt²/8 (second order in the write interval Δt), and so does a
// Maxey–Riley particle driven by it (DU/Dt = ∂U/∂t from the levels' difference). At most three
// levels are held while a run steps through forty; a cycle replays the series;
// bad series are refused with an InputError naming the directory and field (exit status 2 from
// the command line); a run restarted from a checkpoint mid-series ends with the same bits.
#include "../support/case_runs.h"
#include "../support/test_scenes.h"
#include "slides/carrier/foam_carrier.h"
#include "slides/carrier/oscillating_gas.h"
#include "slides/core/error.h"
#include "slides/run/stepper.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <numbers>
#include <string>

#include <unistd.h>

namespace slides {
namespace {

namespace fs = std::filesystem;
using std::numbers::pi;

constexpr double amplitude = 0.2, frequency = 5; // U [m/s], f [Hz]: the series' gas
const Vec3 inside(0.05, 0.01, 0.0);              // a point of the channel

/// Writes the channel case with levels t_n = n·interval, n = 0…count − 1, of U = U sin ωt_n.
fs::path writeSeries(const std::string& name, double interval, int count) {
    const fs::path directory =
        fs::temp_directory_path() / ("slides-series-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(directory);
    fs::create_directories(directory);
    fs::copy(fs::path(SLIDES_SOURCE_DIR) / "tests/foam/data/channel3d/constant",
             directory / "constant", fs::copy_options::recursive);
    for (int n = 0; n < count; ++n) {
        char time[32];
        std::snprintf(time, sizeof time, "%.12g", n * interval);
        fs::create_directories(directory / time);
        const double u = amplitude * std::sin(2 * pi * frequency * n * interval);
        std::ofstream(directory / time / "U")
            << std::setprecision(17)
            << "FoamFile { version 2.0; format ascii; class volVectorField; object U; }\n"
               "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform ("
            << u << " 0 0);\nboundaryField { \".*\" { type fixedValue; value uniform (" << u
            << " 0 0); } }\n";
    }
    return directory;
}

FoamCarrier seriesCarrier(const fs::path& directory, std::optional<double> cycle = {}) {
    return FoamCarrier(directory, {.series = FoamSeriesSettings{std::nullopt, cycle}});
}

Vec3 sampleAt(const CarrierField& carrier, double time, CarrierSample& gas) {
    carrier.holdInterval(time, time);
    carrier.sample(std::span(&inside, 1), time, {.velocityGradient = true, .timeDerivative = true},
                   gas);
    return gas.velocity[0];
}

TEST(FoamSeries, InterpolatesInTimeAtSecondOrderInTheWriteInterval) {
    // Over one period at 400 times: max |U − U sin ωt| ≤ U ω² Δt²/8, and it falls by 4 when
    // Δt halves (order ≥ 1.9); ∂U/∂t at mid-interval is the chord's slope, U ω cos ωt within
    // U ω³ Δt²/24.
    const OscillatingGas exact(Vec3(amplitude, 0, 0), frequency, 293);
    const double omega = 2 * pi * frequency, period = 1 / frequency;
    double previous = 0;
    for (const int levelsPerPeriod : {16, 32, 64}) {
        const double interval = period / levelsPerPeriod;
        const fs::path directory =
            writeSeries(std::to_string(levelsPerPeriod), interval, levelsPerPeriod + 1);
        const FoamCarrier carrier = seriesCarrier(directory);
        EXPECT_FALSE(carrier.steady());
        CarrierSample gas;
        double worst = 0, worstRate = 0;
        for (int k = 0; k <= 400; ++k) {
            const double t = period * k / 400;
            worst = std::max(worst, (sampleAt(carrier, t, gas) - exact.velocity(t)).norm());
            EXPECT_TRUE(gas.velocityGradient[0].isZero(1e-12));
        }
        for (int n = 0; n < levelsPerPeriod; ++n) {
            const double t = (n + 0.5) * interval;
            sampleAt(carrier, t, gas);
            worstRate =
                std::max(worstRate, (gas.velocityTimeDerivative[0] - exact.acceleration(t)).norm());
        }
        const double bound = amplitude * omega * omega * interval * interval / 8;
        std::printf("Δt = T/%d: max |ΔU| = %.3e (bound %.3e), max |Δ∂U/∂t| mid-interval %.3e\n",
                    levelsPerPeriod, worst, bound, worstRate);
        EXPECT_LE(worst, bound * (1 + 1e-9));
        EXPECT_LE(worstRate, amplitude * std::pow(omega * interval, 3) / interval / 24 * 1.001);
        if (previous > 0) {
            EXPECT_GE(std::log2(previous / worst), 1.9);
        }
        previous = worst;
        fs::remove_all(directory);
    }
}

/// Scene of one 200 µm particle in the channel under Stokes drag, added mass and pressure
/// gradient for one period of the gas, in steps of dt.
Scene channelScene(double dt) {
    Scene scene = test::singleParticleScene();
    scene.carrier.type = CarrierType::foamField;
    scene.nozzle.centre = inside;
    scene.particles.density = 10; // light, so that the fluid acceleration matters
    scene.particles.radius.value = 200e-6;
    scene.physics.drag = DragModel::stokes;
    scene.physics.addedMass = scene.physics.pressureGradient = true;
    scene.time.dt = dt;
    scene.time.endTime = 1 / frequency;
    return scene;
}

/// The particle's velocity at the end through carrier; levels: most levels held after a step.
Vec3 finalVelocity(const Scene& scene, const CarrierField& carrier, std::size_t* levels = nullptr) {
    Stepper stepper(scene, carrier);
    const auto* foam = dynamic_cast<const FoamCarrier*>(&carrier);
    while (!stepper.finished()) {
        stepper.step();
        if (levels && foam) *levels = std::max(*levels, foam->series()->heldCount());
    }
    return stepper.cloud().velocity.at(0);
}

TEST(FoamSeries, ParticleThroughTheSeriesConvergesToTheAnalyticGasAtSecondOrder) {
    // The same particle through the analytic gas and through series of it written every
    // Δt = T/10, T/20, T/40 (particle steps Δt/8 in both): the velocity difference at the end
    // falls as Δt² (order ≥ 1.9), and no more than three levels are ever held (40 written).
    const OscillatingGas exact(Vec3(amplitude, 0, 0), frequency, 293);
    double previous = 0;
    for (const int levelsPerPeriod : {10, 20, 40}) {
        const double interval = 1 / frequency / levelsPerPeriod;
        const fs::path directory = writeSeries("particle" + std::to_string(levelsPerPeriod),
                                               interval, levelsPerPeriod + 1);
        const FoamCarrier series = seriesCarrier(directory);
        const Scene scene = channelScene(interval / 8);
        std::size_t held = 0;
        const double difference =
            (finalVelocity(scene, series, &held) - finalVelocity(scene, exact)).norm();
        std::printf("Δt = T/%d: |Δv| at the end %.3e m/s, at most %zu levels held\n",
                    levelsPerPeriod, difference, held);
        EXPECT_LE(held, 3u);
        EXPECT_GE(held, 2u);
        if (previous > 0) {
            EXPECT_GE(std::log2(previous / difference), 1.9);
        }
        previous = difference;
        fs::remove_all(directory);
    }
}

TEST(FoamSeries, WithoutReadAheadTheSameBitsFromOneLevelLess) {
    // readAhead no: each level read when the run reaches it (LevelCache), so inside a write
    // interval the two levels around it are held, not also the next; the particle ends with
    // the same bits as with the next level read on a background thread.
    const double interval = 1 / frequency / 10;
    const fs::path directory = writeSeries("unread", interval, 11);
    const FoamCarrier ahead = seriesCarrier(directory);
    const FoamCarrier unread(directory,
                             {.series = FoamSeriesSettings{std::nullopt, std::nullopt, false}});
    for (const auto* carrier : {&ahead, &unread})
        carrier->holdInterval(2.25 * interval, 2.5 * interval);
    EXPECT_EQ(ahead.series()->heldCount(), 3u);
    EXPECT_EQ(unread.series()->heldCount(), 2u);
    const Scene scene = channelScene(interval / 8);
    const Vec3 withReadAhead = finalVelocity(scene, ahead), without = finalVelocity(scene, unread);
    for (int axis = 0; axis < 3; ++axis) EXPECT_EQ(withReadAhead[axis], without[axis]);
    fs::remove_all(directory);
}

TEST(FoamSeries, CycleReplaysThePeriod) {
    // Levels 0 … T with a cycle of T (the level at T repeats the first and is left out): the
    // gas at t + 2T is the gas at t (to the round-off of t mod T), past the written window.
    const double interval = 1 / frequency / 8;
    const fs::path directory = writeSeries("cycle", interval, 9);
    const FoamCarrier carrier = seriesCarrier(directory, 1 / frequency);
    CarrierSample gas;
    for (const double t : {0.0, 0.3 * interval, 5.5 * interval, 7.9 * interval}) {
        const Vec3 first = sampleAt(carrier, t, gas);
        const Vec3 rate = gas.velocityTimeDerivative[0];
        EXPECT_LT((sampleAt(carrier, t + 2 / frequency, gas) - first).norm(), 1e-14);
        EXPECT_LT((gas.velocityTimeDerivative[0] - rate).norm(), 1e-12);
    }
    fs::remove_all(directory);
}

/// The InputError's message from building a series carrier of directory (empty if none).
std::string refusal(const fs::path& directory, FoamSeriesSettings settings = {}) {
    try {
        FoamCarrier carrier(directory, {.series = settings});
        carrier.holdInterval(0, 1);
    } catch (const InputError& error) {
        return error.what();
    }
    return "";
}

TEST(FoamSeries, RefusesBadSeriesNamingTheDirectoryAndField) {
    const double interval = 0.1;
    const fs::path directory = writeSeries("refusals", interval, 4); // 0 … 0.3
    const auto contains = [](const std::string& message, const std::string& part) {
        return message.find(part) != std::string::npos;
    };
    // Beyond the last level without a cycle (holdInterval to t = 1 s).
    std::string message = refusal(directory);
    EXPECT_TRUE(contains(message, (directory / "0.3").string())) << message;
    EXPECT_TRUE(contains(message, "cycle")) << message;
    // Fewer than two levels in the range.
    message = refusal(directory, {std::pair(0.15, 0.25), std::nullopt});
    EXPECT_TRUE(contains(message, "at least two time directories")) << message;
    EXPECT_TRUE(contains(message, "times")) << message;
    // A level without U.
    fs::rename(directory / "0.2/U", directory / "0.2/U.orig");
    message = refusal(directory);
    EXPECT_TRUE(contains(message, (directory / "0.2/U").string())) << message;
    EXPECT_TRUE(contains(message, "missing field U")) << message;
    fs::rename(directory / "0.2/U.orig", directory / "0.2/U");
    // A mesh inside a time directory: a moving mesh.
    fs::copy(directory / "constant/polyMesh", directory / "0.1/polyMesh");
    message = refusal(directory);
    EXPECT_TRUE(contains(message, (directory / "0.1/polyMesh").string())) << message;
    EXPECT_TRUE(contains(message, "moving")) << message;
    fs::remove_all(directory / "0.1/polyMesh");
    // The control: the same series is accepted over its span.
    FoamCarrier carrier(directory, {.series = FoamSeriesSettings{}});
    EXPECT_NO_THROW(carrier.holdInterval(0, 0.3));
    fs::remove_all(directory);
}

/// The series case for the command line: 41 levels over 0.2 s, ten particles released over
/// 0.05 s under drag, added mass and pressure gradient (the terms that take ∂U/∂t), for endTime.
fs::path writeSeriesCase(const std::string& name, double endTime) {
    const fs::path directory = writeSeries(name, 0.005, 41);
    std::ofstream(directory / "constant/slidesProperties")
        << "FoamFile { version 2.0; format ascii; class dictionary; object slidesProperties; }\n"
           "fluid { density 1.2; kinematicViscosity 1.5e-5; }\n"
           "nozzle { centre (0.05 0.01 0); axis (1 0 0); radius 2e-3; }\n"
           "carrier { type foamField; foamFieldCoeffs { times all; } }\n"
           "particles { count 10; density 50; radiusDistribution { type fixed; value 1e-4; } }\n"
           "injection { mode rate; rate 200; crossSpanSpeed 0.1; seed 3; }\n"
           "physics { drag stokes; history { model none; } addedMass on; pressureGradient on; "
           "lift none; spin off; dispersion { model none; } heatTransfer { model none; } }\n"
           "collisions { model none; }\nsurfaces { }\n"
           "time { dt 1e-3; endTime "
        << endTime << "; }\noutput { interval 0.02; hdf5 on; }\n";
    return directory;
}

TEST(FoamSeries, RestartMidSeriesGivesTheSameBits) {
    // Uninterrupted to 0.2 s, against to 0.083 s (inside the level interval 0.08–0.085, with
    // the next level read ahead) and restarted from its checkpoint: the same positions, bit for
    // bit, in every frame, on 2 threads then 1.
    const fs::path directory = writeSeriesCase("restart", 0.2);
    const std::string run = directory.string() + " --quiet ";
    ASSERT_EQ(test::runCli(run + "--threads 2 --output " + (directory / "reference").string(),
                           directory / "reference.log"),
              0)
        << test::slurp(directory / "reference.log");
    const std::string resumed = (directory / "resumed").string();
    ASSERT_EQ(
        test::runCli(run + "--threads 2 --end-time 0.083 --checkpoint-every 10 --output " + resumed,
                     directory / "first.log"),
        0)
        << test::slurp(directory / "first.log");
    ASSERT_TRUE(fs::exists(directory / "resumed/checkpoint.h5"));
    ASSERT_EQ(
        test::runCli(run + "--threads 1 --restart --output " + resumed, directory / "second.log"),
        0)
        << test::slurp(directory / "second.log");
    for (const char* frame : {"particles_000005.vtp", "particles_000010.vtp"})
        EXPECT_EQ(test::slurp(directory / "resumed" / frame),
                  test::slurp(directory / "reference" / frame))
            << frame;
    const std::string summary = test::slurp(directory / "reference/summary.json");
    EXPECT_NE(summary.find("series of 41 levels"), std::string::npos) << summary;
    fs::remove_all(directory);
}

TEST(FoamSeries, RunBeyondTheSeriesExitsWithStatus2) {
    // endTime 0.3 s on levels to 0.2 s without a cycle: one message naming the last level's
    // directory and the key; with cycle 0.2 the same run goes through.
    const fs::path directory = writeSeriesCase("beyond", 0.3);
    EXPECT_EQ(test::runCli(directory.string() + " --quiet", directory / "log"), 2);
    const std::string message = test::slurp(directory / "log");
    EXPECT_NE(message.find((directory / "0.2").string()), std::string::npos) << message;
    EXPECT_NE(message.find("carrier.foamFieldCoeffs.times"), std::string::npos) << message;
    std::string dictionary = test::slurp(directory / "constant/slidesProperties");
    dictionary.replace(dictionary.find("times all;"), 10, "times all; cycle 0.2;");
    std::ofstream(directory / "constant/slidesProperties") << dictionary;
    EXPECT_EQ(test::runCli(directory.string() + " --quiet", directory / "log"), 0)
        << test::slurp(directory / "log");
    fs::remove_all(directory);
}

} // namespace
} // namespace slides
