// ctest-labels: injection
// Injection (integrate/injector.h, integrate/injector_set.h, integrate/size_distribution.h,
// integrate/particle_file.h): the distributions each model produces, checked on 1e5 draws by
// their moments (tolerance 4 standard errors of the sample, so a correct sampler fails one
// check in about 16 000) and by the Kolmogorov–Smirnov statistic D_n against its 1 % critical
// value 1.628/√n; several injectors against the nozzle + injection form (bit for bit) and in the
// output; chained runs (from a previous run's arrivals, or from its frame at T, which continues
// it bit for bit); OpenFOAM positions lists; Chung & Ooi's (2011) test 4 from a case dictionary
// alone.
#include "../support/case_runs.h"
#include "../support/dem_impact.h"
#include "../support/kolmogorov_smirnov.h"
#include "../support/overlaps.h"
#include "../support/test_scenes.h"
#include "slides/config/dictionary.h"
#include "slides/config/scene_reader.h"
#include "slides/core/error.h"
#include "slides/integrate/injector_set.h"
#include "slides/integrate/size_distribution.h"
#include "slides/io/hdf5_file.h"
#include "slides/io/hdf5_particles.h"
#include "slides/physics/soft_contact.h"
#include "slides/run/stepper.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <numeric>
#include <vector>

namespace slides {
namespace {

constexpr int draws = 100'000;
const double ksCritical = test::kolmogorovSmirnovCritical(draws); // 1 % level
constexpr double degree = std::numbers::pi / 180;

using test::kolmogorovSmirnov;

double mean(const std::vector<double>& values) {
    return std::accumulate(values.begin(), values.end(), 0.0) / double(values.size());
}

double standardDeviation(const std::vector<double>& values) {
    const double m = mean(values);
    double sum = 0;
    for (const double value : values) sum += (value - m) * (value - m);
    return std::sqrt(sum / double(values.size() - 1));
}

/// The sample's median weighted by r³: the mass median of a set of spheres.
double massMedian(std::vector<double> radii) {
    std::sort(radii.begin(), radii.end());
    double total = 0;
    for (const double r : radii) total += r * r * r;
    double below = 0;
    for (const double r : radii) {
        below += r * r * r;
        if (below >= 0.5 * total) return r;
    }
    return radii.back();
}

std::vector<double> radiiOf(const RadiusDistribution& distribution) {
    const RadiusSampler sampler(distribution);
    std::vector<double> radii(draws);
    for (int id = 0; id < draws; ++id) radii[std::size_t(id)] = sampler.draw(7, std::uint64_t(id));
    return radii;
}

/// A case dictionary in a scratch directory, read as the command line reads it.
Scene sceneOf(const test::ScratchDirectory& scratch, const std::string& text) {
    const auto file = scratch.path / "constant" / "slidesProperties";
    std::ofstream(file) << text;
    return readScene(scratch.path);
}

/// The default case's dictionary with the injection part replaced.
std::string sprayDictionary(const std::string& injection, long count) {
    std::string text = test::slurp(test::defaultCase / "constant" / "slidesProperties");
    const auto replace = [&](const std::string& from, const std::string& to) {
        const auto at = text.find(from);
        if (at == std::string::npos) throw std::logic_error("not in the default case: " + from);
        text.replace(at, from.size(), to);
    };
    replace("count       8000;", count > 0 ? "count " + std::to_string(count) + ";" : "");
    const auto start = text.find("injection\n{");
    const auto end = text.find("}\n", start) + 2;
    text.replace(start, end - start, injection);
    return text;
}

/// Every particle the scene's injectors give, all injected.
ParticleCloud injectAll(const Scene& scene) {
    const auto carrier = carrierOf(scene);
    InjectorSet injectors(injectorsOf(scene));
    ParticleCloud cloud;
    injectors.injectUntil(1e300, 0.0, *carrier, cloud);
    return cloud;
}

// ---- several injectors -----------------------------------------------------------------------

const std::string shorthandInjection = R"(
injection { mode rate; rate 8e5; crossSpanSpeed 0.5; seed 1; }
)";
const std::string oneInjector = R"(
injectors { gun { model disc; centre (0 0 0); axis (1 0 0); radius 2e-3; rate 8e5; count 600;
                  crossSpanSpeed 0.5; } }
)";

TEST(SeveralInjectors, OneInjectorRunsBitForBitAsNozzleAndInjection) {
    test::ScratchDirectory a("inject-shorthand"), b("inject-one");
    Scene shorthand = sceneOf(a, sprayDictionary(shorthandInjection, 600));
    Scene listed = sceneOf(b, sprayDictionary(oneInjector, 0));
    ASSERT_EQ(listed.particles.count, 600);
    for (Scene* scene : {&shorthand, &listed}) scene->collisions.model = CollisionModel::none;
    const auto carrier = carrierOf(shorthand);
    Stepper first(shorthand, *carrier), second(listed, *carrier);
    while (!first.finished()) first.step();
    while (!second.finished()) second.step();
    ASSERT_EQ(first.arrivals().size(), 600u);
    ASSERT_EQ(second.arrivals().size(), 600u);
    for (std::size_t k = 0; k < 600; ++k) {
        const Arrival &p = first.arrivals()[k], &q = second.arrivals()[k];
        ASSERT_EQ(p.id, q.id);
        ASSERT_EQ(p.time, q.time);
        ASSERT_TRUE(p.position == q.position && p.velocity == q.velocity) << p.id;
    }
}

const std::string twoGuns = R"(
injectors
{
    upper { model cone; centre (0 0.001 0); axis (1 0 0); radius 0; count 3000; rate 1e5;
            startTime 1e-3; coneCoeffs { outerHalfAngle 5; speed 20; } }
    lower { model disc; centre (0 -0.0005 0); axis (1 0 0); radius 1e-3; count 5000;
            duration 2e-2; crossSpanSpeed 0.5;
            radiusDistribution { type fixed; value 40e-6; } }
}
collisions { model none; }
)";

TEST(SeveralInjectors, IdsInInjectorBlocksEachOnItsOwnDiscAndSchedule) {
    test::ScratchDirectory scratch("inject-two");
    const Scene scene = sceneOf(scratch, sprayDictionary(twoGuns, 0));
    ASSERT_EQ(scene.particles.count, 8000);
    ASSERT_EQ(scene.injectors.size(), 2u);
    EXPECT_EQ(scene.injectors[1].firstId, 3000u);
    EXPECT_EQ(scene.injectors[1].injection.rate, 5000 / 2e-2); // count / duration
    const ParticleCloud cloud = injectAll(scene);
    ASSERT_EQ(cloud.size(), 8000u);
    const InjectorSet injectors(scene.injectors);
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        ASSERT_EQ(cloud.id[i], i); // unique, in blocks, injector by injector
        const InjectorSettings& injector = scene.injectors[i < 3000 ? 0 : 1];
        const Vec3 offset = cloud.position[i] - injector.nozzle.centre;
        ASSERT_NEAR(offset.dot(injector.nozzle.axis), 0, 1e-15);
        ASSERT_LE(offset.norm(), injector.nozzle.radius * (1 + 1e-12));
        ASSERT_EQ(cloud.radius[i], i < 3000 ? 80e-6 : 40e-6);
        const double k = double(i - injector.firstId);
        ASSERT_EQ(injectors.injectionTime(i), injector.startTime + k / injector.injection.rate);
        ASSERT_EQ(injectors.injectorOf(i), i < 3000 ? 0 : 1);
    }
}

/// The two guns with 300 (upper: ids 0–299) and 500 particles, as scratch's dictionary.
void writeSmallTwoGuns(const test::ScratchDirectory& scratch) {
    std::string text = sprayDictionary(twoGuns, 0);
    text.replace(text.find("count 3000"), 10, "count 300")
        .replace(text.find("count 5000"), 10, "count 500");
    std::ofstream(scratch.path / "constant" / "slidesProperties") << text;
}

TEST(SeveralInjectors, FramesAndSummaryRecordWhichInjectorEachParticleCameFrom) {
    test::ScratchDirectory scratch("inject-output");
    writeSmallTwoGuns(scratch);
    const auto output = scratch.path / "out";
    ASSERT_EQ(test::runCli(scratch.path.string() + " --quiet --output " + output.string(),
                           scratch.path / "log"),
              0)
        << test::slurp(scratch.path / "log");
    const auto summary = nlohmann::json::parse(test::slurp(output / "summary.json"));
    const auto& byInjector = summary["particles"]["arrivedByInjector"];
    const long upper = byInjector["upper"]["target"], lower = byInjector["lower"]["target"];
    EXPECT_EQ(upper + lower, summary["particles"]["arrived"]["target"].get<long>());
    EXPECT_GT(upper, 0);
    EXPECT_GT(lower, 0);

    const Hdf5File h5(output / "particles.h5", Hdf5Access::readOnly);
    const auto arrivalIds = h5.readUInt64("/arrivals/id");
    EXPECT_EQ(std::count_if(arrivalIds.begin(), arrivalIds.end(), [](auto id) { return id < 300; }),
              upper);
    std::string last;
    for (int frame = 0; h5.exists("/frames/" + std::string(6 - std::to_string(frame).size(), '0') +
                                  std::to_string(frame));
         ++frame)
        last =
            "/frames/" + std::string(6 - std::to_string(frame).size(), '0') + std::to_string(frame);
    const auto ids = h5.readUInt64(last + "/id");
    const auto injector = h5.readInt32(last + "/injector");
    ASSERT_EQ(ids.size(), 800 - summary["particles"]["escaped"].get<std::size_t>());
    for (std::size_t i = 0; i < ids.size(); ++i) ASSERT_EQ(injector[i], ids[i] < 300 ? 0 : 1);
    const std::string vtp = test::slurp(output / "particles_000001.vtp");
    EXPECT_NE(vtp.find("Name=\"injector\""), std::string::npos);
}

// A restart writes the HDF5 frames before its checkpoint anew from their .vtp files: they keep
// the injector array as the frames written after it do.
TEST(SeveralInjectors, RestartedRunsFramesKeepTheInjectorArray) {
    test::ScratchDirectory scratch("inject-restart-frames");
    writeSmallTwoGuns(scratch);
    const std::string run =
        scratch.path.string() + " --quiet --output " + (scratch.path / "out").string();
    ASSERT_EQ(test::runCli(run + " --checkpoint-every 100", scratch.path / "log"), 0)
        << test::slurp(scratch.path / "log");
    ASSERT_EQ(test::runCli(run + " --restart", scratch.path / "log"), 0)
        << test::slurp(scratch.path / "log");
    const Hdf5File h5(scratch.path / "out" / "particles.h5", Hdf5Access::readOnly);
    const auto frames = h5.readInt64("/", "frames");
    ASSERT_GT(frames, 2);
    for (std::int64_t frame = 0; frame < frames; ++frame) {
        char group[32];
        std::snprintf(group, sizeof group, "/frames/%06lld", static_cast<long long>(frame));
        const auto ids = h5.readUInt64(std::string(group) + "/id");
        const auto injector = h5.readInt32(std::string(group) + "/injector");
        ASSERT_EQ(injector.size(), ids.size()) << group;
        for (std::size_t i = 0; i < ids.size(); ++i)
            ASSERT_EQ(injector[i], ids[i] < 300 ? 0 : 1) << group;
    }
}

TEST(SeveralInjectors, RestartResumesEachInjectorWhereItStood) {
    test::ScratchDirectory scratch("inject-restart");
    const Scene scene = sceneOf(scratch, sprayDictionary(twoGuns, 0));
    const auto carrier = carrierOf(scene);
    Stepper whole(scene, *carrier), resumed(scene, *carrier);
    for (int step = 0; step < 150; ++step) whole.step();
    Stepper half(scene, *carrier);
    for (int step = 0; step < 75; ++step) half.step();
    // The upper gun (from 1 ms, 1e5/s) and the lower (from 0, 2.5e5/s) stand at different
    // shares of their blocks after 0.75 ms.
    resumed.resume(half.counters(), half.cloud(), half.arrivals());
    for (int step = 0; step < 75; ++step) resumed.step();
    EXPECT_EQ(resumed.injected(), whole.injected());
    ASSERT_EQ(resumed.cloud().size(), whole.cloud().size());
    for (std::size_t i = 0; i < whole.cloud().size(); ++i) {
        ASSERT_EQ(resumed.cloud().id[i], whole.cloud().id[i]);
        ASSERT_TRUE(resumed.cloud().position[i] == whole.cloud().position[i]);
    }
}

TEST(SeveralInjectors, CollidingRunOfTwoInjectorsIsTheSameForOneAndTwoThreads) {
    // Both injectors into one spray, impulse collisions and the overlap-free placement on.
    test::ScratchDirectory scratch("inject-threads");
    std::string text = sprayDictionary(twoGuns, 0);
    text.replace(text.find("collisions { model none; }"), 26, "collisions { model impulse; }");
    Scene scene = sceneOf(scratch, text);
    const auto carrier = carrierOf(scene);
    std::vector<Arrival> arrivals[2];
    long contacts[2] = {0, 0};
    for (int threads = 1; threads <= 2; ++threads) {
        omp_set_num_threads(threads);
        Stepper stepper(scene, *carrier);
        for (int step = 0; step < 800; ++step) stepper.step();
        arrivals[threads - 1] = stepper.arrivals();
        contacts[threads - 1] = stepper.collisions();
    }
    omp_set_num_threads(omp_get_num_procs());
    EXPECT_GT(contacts[0], 0);
    EXPECT_EQ(contacts[0], contacts[1]);
    ASSERT_GT(arrivals[0].size(), 100u);
    ASSERT_EQ(arrivals[0].size(), arrivals[1].size());
    for (std::size_t k = 0; k < arrivals[0].size(); ++k) {
        ASSERT_EQ(arrivals[0][k].id, arrivals[1][k].id);
        ASSERT_TRUE(arrivals[0][k].position == arrivals[1][k].position);
        ASSERT_TRUE(arrivals[0][k].velocity == arrivals[1][k].velocity);
    }
}

TEST(SeveralInjectors, BadInjectorsAreRefusedAtTheirKey) {
    test::ScratchDirectory scratch("inject-refusals");
    const auto refusal = [&](const std::string& injection) {
        try {
            sceneOf(scratch, sprayDictionary(injection, 0));
        } catch (const InputError& error) {
            return error.key() + ": " + error.reason();
        }
        return std::string("accepted");
    };
    EXPECT_EQ(refusal("injectors { a { count 10; rate 1e3; duration 1; } }"),
              "injectors.a.count: give two of count, rate and duration (mode rate)");
    EXPECT_EQ(refusal("injectors { a { model cone; count 10; rate 1e3; coneCoeffs { "
                      "innerHalfAngle 20; outerHalfAngle 10; speed 5; } } }"),
              "injectors.a.coneCoeffs.outerHalfAngle: must be larger than innerHalfAngle");
    EXPECT_EQ(refusal("injectors { a { count 10; rate 1e3; susceptibility 0.5; } }"),
              "injectors.a.susceptibility: acts with physics.electromagnetic.magnetisation.model "
              "linear");
    EXPECT_EQ(refusal("injectors { a { count 10; rate 1e3; susceptibility -1; } }\nphysics { "
                      "electromagnetic { model lorentz; coils { c { radius 0.01; current 1; } } "
                      "magnetisation { model linear; } } }"),
              "injectors.a.susceptibility: must be above −1 (µr = 1 + χm > 0)");
    EXPECT_EQ(refusal("injectors { a { model sprinkler; } }"),
              "injectors.a.model: unknown model 'sprinkler'; valid model names are:\n    disc\n"
              "    cone\n    file\n    patch\n    ensemble");
    EXPECT_EQ(refusal("injectors { a { count 10; rate 1e3; } }\ninjection { rate 5; }"),
              "injection.rate: with injectors, injection gives only the seed");
    EXPECT_EQ(refusal("injectors { a { count 10; rate 1e3; radiusDistribution { type normal; "
                      "mean 1e-5; standardDeviation 1e-6; weighting mass; } } }"),
              "injectors.a.radiusDistribution.weighting: mass weighting is for types fixed, "
              "logNormal, rosinRammler and table");
    EXPECT_EQ(refusal("injectors { a { count 10; rate 1e3; radiusDistribution { type "
                      "rosinRammler; scale 1e-5; spread 2; weighting mass; } } }"),
              "injectors.a.radiusDistribution.minimum: a mass-weighted rosinRammler needs "
              "minimum > 0 (its number of particles grows without bound as r → 0)");
    // Each injector is checked inside the domain box (run/injection_check.h).
    std::ofstream(scratch.path / "constant" / "slidesProperties")
        << sprayDictionary("injectors { a { count 10; rate 1e3; } b { centre (0 0.029 0); "
                           "radius 2e-3; count 10; rate 1e3; } }",
                           0);
    EXPECT_EQ(test::runCli(scratch.path.string() + " --quiet", scratch.path / "log"), 2);
    EXPECT_NE(test::slurp(scratch.path / "log")
                  .find("key 'injectors.b.radius': the disc of injector b of radius 0.002 m is "
                        "not inside the domain box"),
              std::string::npos)
        << test::slurp(scratch.path / "log");
}

// ---- constant mass flow: re-injecting escaped particles (Section 5.2.4) ----------------------

// Two guns in a domain box that ends at x = 0.02 m, before the target (0.06 m): every particle
// escapes through the box, ~1 ms after it enters. The upper gun (ids 0–399, 1–5 ms) replaces
// its escaped particles; the lower (ids 400–599, 0–2 ms) does not.
const std::string escapingGuns = R"(
injectors
{
    upper { model cone; centre (0 0.001 0); axis (1 0 0); radius 0; count 400; rate 1e5;
            startTime 1e-3; reinjectEscaped yes; coneCoeffs { outerHalfAngle 5; speed 20; } }
    lower { model disc; centre (0 -0.0005 0); axis (1 0 0); radius 1e-3; count 200; rate 1e5;
            crossSpanSpeed 0.5; radiusDistribution { type fixed; value 40e-6; } }
}
collisions { model none; }
)";

/// The default case with escapingGuns, its domain box cut at x = 0.02 m, ending at 8 ms.
std::string escapingGunsDictionary() {
    std::string text = sprayDictionary(escapingGuns, 0);
    text.replace(text.find("max     (0.065 0.03 0.03);"), 26, "max (0.02 0.03 0.03);");
    text.replace(text.find("endTime         0.1;"), 20, "endTime 8e-3;");
    return text;
}

constexpr long upperCount = 400, gunsCount = 600;

/// The particles of the cloud that came from injector (ids: InjectorIds).
long inFlightFrom(const Stepper& stepper, const InjectorIds& ids, std::int32_t injector) {
    const auto& id = stepper.cloud().id;
    return std::count_if(id.begin(), id.end(),
                         [&](ParticleId i) { return ids.injectorOf(i) == injector; });
}

TEST(ConstantMassFlow, ReinjectionKeepsTheInjectorsParticlesInFlightAndConservesTheCount) {
    test::ScratchDirectory scratch("reinject-count");
    const Scene scene = sceneOf(scratch, escapingGunsDictionary());
    const InjectorIds ids = injectorIds(scene);
    const auto carrier = carrierOf(scene);
    Stepper stepper(scene, *carrier);
    long stepsAfterInjection = 0;
    while (!stepper.finished()) {
        stepper.step();
        const auto& counters = stepper.counters();
        ASSERT_EQ(counters.reinjected.size(), 2u);
        // Conservation: every particle injected, first or again, is in flight, escaped or
        // arrived, exactly.
        ASSERT_EQ(stepper.injected() + long(counters.reinjected[0] + counters.reinjected[1]),
                  long(stepper.cloud().size()) + stepper.escaped() +
                      long(stepper.arrivals().size()));
        ASSERT_EQ(counters.reinjected[1], 0u); // the lower gun does not re-inject
        if (stepper.time() < 5e-3 - 1e-12) continue;
        // Injection over (400 at 1e5/s from 1 ms): the upper gun's particles stay 400.
        ASSERT_EQ(inFlightFrom(stepper, ids, 0), upperCount) << "t = " << stepper.time();
        ++stepsAfterInjection;
    }
    EXPECT_EQ(stepsAfterInjection, 301); // t = 5 ms … 8 ms at dt = 1e-5 s
    EXPECT_EQ(stepper.arrivals().size(), 0u);
    EXPECT_EQ(inFlightFrom(stepper, ids, 1), 0); // the lower gun's all escaped, not replaced
    // About 3 ms of 400 particles a ms-long flight apart: hundreds replaced, each escape of an
    // upper particle once.
    const auto reinjected = long(stepper.counters().reinjected[0]);
    EXPECT_GT(reinjected, 400);
    EXPECT_EQ(stepper.escaped(), reinjected + 200);
    // New ids beyond both blocks, interleaved: 600 + 2 m for the upper gun, unique.
    std::vector<ParticleId> inFlight = stepper.cloud().id;
    std::sort(inFlight.begin(), inFlight.end());
    EXPECT_EQ(std::adjacent_find(inFlight.begin(), inFlight.end()), inFlight.end());
    EXPECT_GE(inFlight.back(), ParticleId(gunsCount));
    EXPECT_LT(inFlight.back(), ParticleId(gunsCount + 2 * reinjected));
    for (const ParticleId id : inFlight) {
        if (id >= ParticleId(gunsCount)) {
            ASSERT_EQ((id - gunsCount) % 2, 0u) << id;
        }
    }
}

TEST(ConstantMassFlow, ReinjectingRunIsTheSameForOneAndTwoThreadsAndAcrossARestart) {
    test::ScratchDirectory scratch("reinject-threads");
    const Scene scene = sceneOf(scratch, escapingGunsDictionary());
    const auto carrier = carrierOf(scene);
    constexpr int steps = 700;
    std::vector<ParticleCloud> clouds;
    for (int threads = 1; threads <= 2; ++threads) {
        omp_set_num_threads(threads);
        Stepper stepper(scene, *carrier);
        for (int step = 0; step < steps; ++step) stepper.step();
        ASSERT_GT(stepper.cloud().size(), 256u); // the particle loops run on both threads
        clouds.push_back(stepper.cloud());
    }
    omp_set_num_threads(omp_get_num_procs());
    Stepper half(scene, *carrier), resumed(scene, *carrier);
    for (int step = 0; step < steps / 2; ++step) half.step();
    ASSERT_GT(half.counters().reinjected[0], 0u); // the restart falls amid the re-injections
    resumed.resume(half.counters(), half.cloud(), half.arrivals());
    for (int step = steps / 2; step < steps; ++step) resumed.step();
    clouds.push_back(resumed.cloud());
    for (std::size_t run = 1; run < clouds.size(); ++run) {
        ASSERT_EQ(clouds[run].size(), clouds[0].size()) << run;
        for (std::size_t i = 0; i < clouds[0].size(); ++i) {
            ASSERT_EQ(clouds[run].id[i], clouds[0].id[i]) << run;
            ASSERT_TRUE(clouds[run].position[i] == clouds[0].position[i]) << run;
            ASSERT_TRUE(clouds[run].velocity[i] == clouds[0].velocity[i]) << run;
        }
    }
}

TEST(ConstantMassFlow, SummaryCountsTheReinjectedAndACheckpointKeepsTheCount) {
    test::ScratchDirectory scratch("reinject-summary");
    std::ofstream(scratch.path / "constant" / "slidesProperties") << escapingGunsDictionary();
    const auto summaryOf = [&](const std::string& options, const std::string& out) {
        const std::string run = scratch.path.string() + " --quiet --output " +
                                (scratch.path / out).string() + " " + options;
        EXPECT_EQ(test::runCli(run, scratch.path / "log"), 0) << test::slurp(scratch.path / "log");
        return nlohmann::json::parse(test::slurp(scratch.path / out / "summary.json"));
    };
    const auto whole = summaryOf("", "whole");
    summaryOf("--checkpoint-every 300", "restarted");
    const auto restarted = summaryOf("--restart", "restarted");
    const auto& particles = whole["particles"];
    const long reinjected = particles["reinjected"];
    EXPECT_GT(reinjected, 400);
    EXPECT_EQ(particles["reinjectedByInjector"]["upper"].get<long>(), reinjected);
    EXPECT_EQ(particles["reinjectedByInjector"]["lower"].get<long>(), 0);
    EXPECT_EQ(particles["injected"].get<long>(), gunsCount);
    EXPECT_EQ(particles["active"].get<long>(), upperCount);
    EXPECT_EQ(particles["escaped"].get<long>(), reinjected + 200);
    for (const char* count : {"reinjected", "escaped", "active"})
        EXPECT_EQ(restarted["particles"][count], particles[count]) << count;
    // The last frame names the upper gun for its re-injected particles.
    const Hdf5File h5(scratch.path / "whole" / "particles.h5", Hdf5Access::readOnly);
    char last[32];
    std::snprintf(last, sizeof last, "/frames/%06lld",
                  static_cast<long long>(h5.readInt64("/", "frames") - 1));
    const auto ids = h5.readUInt64(std::string(last) + "/id");
    const auto injector = h5.readInt32(std::string(last) + "/injector");
    ASSERT_EQ(ids.size(), std::size_t(upperCount));
    for (std::size_t i = 0; i < ids.size(); ++i) ASSERT_EQ(injector[i], 0) << ids[i];
}

TEST(ConstantMassFlow, OffByDefaultAndBadValuesAreRefusedAtTheirKey) {
    test::ScratchDirectory scratch("reinject-refusals");
    const Scene off = sceneOf(scratch, sprayDictionary(twoGuns, 0));
    for (const InjectorSettings& injector : off.injectors)
        EXPECT_FALSE(injector.injection.reinjectEscaped);
    const auto refusal = [&](const std::string& injection, long count = 0) {
        try {
            sceneOf(scratch, sprayDictionary(injection, count));
        } catch (const InputError& error) {
            return error.key() + ": " + error.reason();
        }
        return std::string("accepted");
    };
    EXPECT_EQ(refusal("injection { mode lattice; reinjectEscaped yes; latticeCoeffs { spacing "
                      "1e-3; sites (10 10 10); } }",
                      100),
              "injection.reinjectEscaped: a lattice's sites are filled once");
    EXPECT_EQ(refusal("injectors { a { count 10; rate 1e3; } }\n"
                      "injection { reinjectEscaped yes; }"),
              "injection.reinjectEscaped: with injectors, injection gives only the seed");
    // A value that is no switch: exit status 2, the message naming file, line and key.
    std::string text = escapingGunsDictionary();
    const auto at = text.find("reinjectEscaped yes;");
    text.replace(at, 20, "reinjectEscaped maybe;");
    const auto line = 1 + std::count(text.begin(), text.begin() + long(at), '\n');
    std::ofstream(scratch.path / "constant" / "slidesProperties") << text;
    EXPECT_EQ(test::runCli(scratch.path.string() + " --quiet", scratch.path / "log"), 2);
    const std::string log = test::slurp(scratch.path / "log");
    EXPECT_NE(log.find("slidesProperties:" + std::to_string(line) +
                       ": key 'injectors.upper.reinjectEscaped'"),
              std::string::npos)
        << log;
}

TEST(CheckOption, ReadsAndAnalysesTheCaseAndWritesNothing) {
    test::ScratchDirectory scratch("inject-check");
    std::ofstream(scratch.path / "constant" / "slidesProperties") << sprayDictionary(twoGuns, 0);
    ASSERT_EQ(test::runCli(scratch.path.string() + " --check", scratch.path / "log"), 0);
    const std::string log = test::slurp(scratch.path / "log");
    EXPECT_NE(log.find("decision (threshold 0.01)"), std::string::npos) << log;
    EXPECT_NE(log.find("nothing written"), std::string::npos) << log;
    EXPECT_FALSE(std::filesystem::exists(scratch.path / "slides"));
    // A bad case is refused as a run would refuse it.
    std::ofstream(scratch.path / "constant" / "slidesProperties")
        << sprayDictionary("injectors { a { count 10; } }", 0);
    EXPECT_EQ(test::runCli(scratch.path.string() + " --check", scratch.path / "log"), 2);
    EXPECT_FALSE(std::filesystem::exists(scratch.path / "slides"));
}

/// The share of particles placed overlapping another (in flight or placed before them) when the
/// default spray's 4000 particles of 80 µm enter at 8e5/s through its 2 mm disc, 8 a step of
/// 10 µs, and fly on ballistically.
double overlappingShare(bool avoidOverlap) {
    test::ScratchDirectory scratch("inject-overlap");
    const Scene scene = sceneOf(scratch, sprayDictionary(shorthandInjection, 4000));
    const auto carrier = carrierOf(scene);
    InjectorSet injectors(injectorsOf(scene), avoidOverlap);
    ParticleCloud cloud;
    long overlapping = 0;
    const double dt = 1e-5;
    for (double t = 0; !injectors.finished(); t += dt) {
        const std::size_t before = cloud.size();
        injectors.injectUntil(t + dt, t, *carrier, cloud);
        overlapping += test::overlappingNewcomers(cloud, before);
        for (std::size_t i = 0; i < cloud.size(); ++i) cloud.position[i] += dt * cloud.velocity[i];
    }
    return double(overlapping) / double(cloud.size());
}

TEST(OverlapFreeInjection, NoParticlePlacedOverlappingOneNearTheInjector) {
    // Without the rule about 2 % overlap (pairs among the 8 of a step: 28 pairs at
    // π(160 µm)²/π(2 mm)² = 0.64 % each, over 8 particles); with it none.
    const double without = overlappingShare(false);
    EXPECT_GT(without, 0.01);
    EXPECT_LT(without, 0.04);
    EXPECT_EQ(overlappingShare(true), 0.0);
}

// ---- cone ----------------------------------------------------------------------------------

/// The directions and speeds of 1e5 particles of a cone injector (no gas is sampled for them).
struct ConeDraws {
    std::vector<double> cosPolar, azimuth, speed;
    std::vector<Vec3> position;
};

ConeDraws coneDraws(const ConeSettings& cone, double discRadius) {
    InjectorSettings settings;
    settings.model = InjectionModel::cone;
    settings.nozzle = {Vec3(0.1, 0.2, 0.3), Vec3(0, 0, 1), discRadius, Vec3(1, 0, 0)};
    settings.injection.mode = InjectionMode::allAtStart;
    settings.count = draws;
    settings.radius.value = 1e-5;
    settings.cone = cone;
    Injector injector(settings);
    ParticleCloud cloud;
    const test::UniformFlow still(Vec3::Zero());
    injector.injectUntil(1, 0, still, cloud);
    ConeDraws out;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const Vec3& v = cloud.velocity[i];
        out.speed.push_back(v.norm());
        out.cosPolar.push_back(v.z() / v.norm());
        out.azimuth.push_back(std::atan2(v.y(), v.x()));
        out.position.push_back(cloud.position[i]);
    }
    return out;
}

TEST(ConeInjection, HollowConeIsUniformOverItsBandOfTheSphereWithNormalSpeeds) {
    const ConeSettings cone{10 * degree, 25 * degree, 30, 3};
    const ConeDraws d = coneDraws(cone, 1e-3);
    // Uniform on the spherical band: cos θ uniform on [cos θ_out, cos θ_in] (Archimedes).
    const double c0 = std::cos(cone.outerHalfAngle), c1 = std::cos(cone.innerHalfAngle);
    EXPECT_LT(kolmogorovSmirnov(
                  d.cosPolar, [&](double c) { return std::clamp((c - c0) / (c1 - c0), 0.0, 1.0); }),
              ksCritical);
    EXPECT_LT(
        kolmogorovSmirnov(d.azimuth,
                          [](double a) { return (a + std::numbers::pi) / (2 * std::numbers::pi); }),
        ksCritical);
    EXPECT_GE(*std::min_element(d.cosPolar.begin(), d.cosPolar.end()), c0 - 1e-12);
    EXPECT_LE(*std::max_element(d.cosPolar.begin(), d.cosPolar.end()), c1 + 1e-12);
    // Speed N(30, 3): mean to 4 σ/√n, standard deviation to 4 σ/√(2n).
    EXPECT_NEAR(mean(d.speed), 30, 4 * 3 / std::sqrt(double(draws)));
    EXPECT_NEAR(standardDeviation(d.speed), 3, 4 * 3 / std::sqrt(2.0 * draws));
    // From the disc: the start points uniform in its area, r²/R² uniform.
    std::vector<double> areaFraction;
    for (const Vec3& x : d.position)
        areaFraction.push_back((x - Vec3(0.1, 0.2, 0.3)).squaredNorm() / 1e-6);
    EXPECT_LT(kolmogorovSmirnov(areaFraction, [](double f) { return std::clamp(f, 0.0, 1.0); }),
              ksCritical);
}

TEST(ConeInjection, SolidConeFromAPointHasTheCapLawAndAFixedSpeed) {
    const ConeSettings cone{0, 40 * degree, 12, 0};
    const ConeDraws d = coneDraws(cone, 0);
    // P(θ < x) = (1 − cos x)/(1 − cos θ_out): the cap's area share.
    std::vector<double> polar;
    for (const double c : d.cosPolar) polar.push_back(std::acos(std::clamp(c, -1.0, 1.0)));
    const double cap = 1 - std::cos(cone.outerHalfAngle);
    EXPECT_LT(kolmogorovSmirnov(
                  polar, [&](double x) { return std::clamp((1 - std::cos(x)) / cap, 0.0, 1.0); }),
              ksCritical);
    // Its mean: E[θ] over the cap, (sin θ − θ cos θ)|₀^θout / (1 − cos θout); sample σ_θ/√n.
    const double outer = cone.outerHalfAngle;
    const double expected = (std::sin(outer) - outer * std::cos(outer)) / cap;
    EXPECT_NEAR(mean(polar), expected, 4 * standardDeviation(polar) / std::sqrt(double(draws)));
    for (std::size_t i = 0; i < d.speed.size(); ++i) {
        ASSERT_NEAR(d.speed[i], 12, 1e-12);
        ASSERT_TRUE(d.position[i] == Vec3(0.1, 0.2, 0.3));
    }
}

// ---- size distributions --------------------------------------------------------------------

RadiusDistribution rosinRammler(double scale, double spread, double minimum, double maximum,
                                SizeWeighting weighting) {
    RadiusDistribution distribution;
    distribution.kind = RadiusDistributionKind::rosinRammler;
    distribution.scale = scale;
    distribution.spread = spread;
    distribution.minimum = minimum;
    distribution.maximum = maximum;
    distribution.weighting = weighting;
    return distribution;
}

TEST(SizeDistribution, RosinRammlerTruncatedHasItsCumulativeLawAndMean) {
    const double scale = 20e-6, n = 2.5, lo = 5e-6, hi = 40e-6;
    const std::vector<double> radii =
        radiiOf(rosinRammler(scale, n, lo, hi, SizeWeighting::number));
    const double F0 = rosinRammlerCumulative(lo, scale, n),
                 F1 = rosinRammlerCumulative(hi, scale, n);
    EXPECT_LT(kolmogorovSmirnov(radii,
                                [&](double r) {
                                    return std::clamp((rosinRammlerCumulative(r, scale, n) - F0) /
                                                          (F1 - F0),
                                                      0.0, 1.0);
                                }),
              ksCritical);
    // Mean of the truncated law by Simpson's rule on 20 000 intervals (independent of the
    // sampler's table), to 4 standard errors.
    const int intervals = 20'000;
    double mass = 0, moment = 0;
    for (int k = 0; k <= intervals; ++k) {
        const double r = lo + (hi - lo) * k / intervals;
        const double x = std::pow(r / scale, n);
        const double density = n / r * x * std::exp(-x);
        const double weight = (k == 0 || k == intervals) ? 1 : (k % 2 ? 4 : 2);
        mass += weight * density;
        moment += weight * density * r;
    }
    EXPECT_NEAR(mean(radii), moment / mass,
                4 * standardDeviation(radii) / std::sqrt(double(draws)));
    EXPECT_NEAR(RadiusSampler(rosinRammler(scale, n, lo, hi, SizeWeighting::number)).meanRadius(),
                moment / mass, 1e-6 * moment / mass);
    EXPECT_GE(*std::min_element(radii.begin(), radii.end()), lo);
    EXPECT_LE(*std::max_element(radii.begin(), radii.end()), hi);
}

TEST(SizeDistribution, MassWeightedRosinRammlerHasTheNumberLawAndTheGivenMassMedian) {
    // A mass-median radius of 30 µm, n = 3, from 2 µm: the number law f_n ∝ f_m / r³.
    const double scale = 30e-6 / std::cbrt(std::log(2.0)), n = 3, lo = 2e-6;
    const std::vector<double> radii =
        radiiOf(rosinRammler(scale, n, lo, INFINITY, SizeWeighting::mass));
    // The number CDF by the trapezoid rule in r on 200 000 intervals up to 6 r̄ (e^(−216) beyond).
    const int intervals = 200'000;
    const double hi = 6 * scale, h = (hi - lo) / intervals;
    std::vector<double> cumulative(intervals + 1, 0.0);
    const auto density = [&](double r) {
        const double x = std::pow(r / scale, n);
        return n / r * x * std::exp(-x) / (r * r * r);
    };
    for (int k = 1; k <= intervals; ++k)
        cumulative[k] =
            cumulative[k - 1] + 0.5 * h * (density(lo + (k - 1) * h) + density(lo + k * h));
    for (double& c : cumulative) c /= cumulative.back();
    EXPECT_LT(kolmogorovSmirnov(radii,
                                [&](double r) {
                                    const double at =
                                        std::clamp((r - lo) / h, 0.0, double(intervals) - 1e-9);
                                    const auto k = std::size_t(at);
                                    return cumulative[k] +
                                           (at - double(k)) * (cumulative[k + 1] - cumulative[k]);
                                }),
              ksCritical);
    // The mass median of the drawn spheres is the mass median asked for (the truncation at
    // 2 µm removes 3e-4 of the mass): within 4 standard errors of the r³-weighted median, whose
    // effective sample size (Σw)²/Σw² is about 1 % of the draws.
    double sum = 0, squares = 0;
    for (const double r : radii) {
        sum += r * r * r;
        squares += std::pow(r, 6);
    }
    const double effective = sum * sum / squares;
    // The truncated mass law's median: e^(−x) = e^(−x_lo)/2, x = (r/r̄)^n.
    const double median = scale * std::cbrt(std::log(2.0) + std::pow(lo / scale, n));
    const double massDensityAtMedian = n / median * std::log(2.0) * 0.5; // f_m(r_50)
    EXPECT_NEAR(massMedian(radii), median, 4 * 0.5 / std::sqrt(effective) / massDensityAtMedian);
}

TEST(SizeDistribution, MassWeightedLogNormalIsTheHatchChoateNumberLaw) {
    RadiusDistribution distribution;
    distribution.kind = RadiusDistributionKind::logNormal;
    distribution.median = 25e-6; // a mass-median radius
    distribution.geometricStandardDeviation = 1.6;
    distribution.maximum = INFINITY;
    distribution.weighting = SizeWeighting::mass;
    const std::vector<double> radii = radiiOf(distribution);
    const double sigma = std::log(1.6), numberMedian = 25e-6 * std::exp(-3 * sigma * sigma);
    EXPECT_LT(kolmogorovSmirnov(radii,
                                [&](double r) {
                                    return 0.5 * std::erfc(-std::log(r / numberMedian) /
                                                           (sigma * std::sqrt(2.0)));
                                }),
              ksCritical);
    EXPECT_NEAR(distribution.meanRadius(), numberMedian * std::exp(0.5 * sigma * sigma), 1e-18);
}

TEST(SizeDistribution, MeasuredTableNumberAndMassWeighted) {
    test::ScratchDirectory scratch("inject-size-table");
    const auto file = scratch.path / "constant" / "sizes.csv";
    std::ofstream(file) << "# a measured distribution\nd F\n10e-6 0\n20e-6 0.1\n40e-6 0.6\n"
                           "60e-6 0.9\n100e-6 1\n";
    RadiusDistribution distribution;
    distribution.kind = RadiusDistributionKind::table;
    readSizeTable(file, distribution);
    const std::vector<double> r{5e-6, 10e-6, 20e-6, 30e-6, 50e-6}, F{0, 0.1, 0.6, 0.9, 1};
    ASSERT_EQ(distribution.tableRadius, r);
    // Number-weighted: linear between the rows.
    const auto table = [&](double x) {
        const auto i = std::size_t(std::upper_bound(r.begin(), r.end(), x) - r.begin());
        if (i == 0) return 0.0;
        if (i == r.size()) return 1.0;
        return F[i - 1] + (x - r[i - 1]) / (r[i] - r[i - 1]) * (F[i] - F[i - 1]);
    };
    const std::vector<double> number = radiiOf(distribution);
    EXPECT_LT(kolmogorovSmirnov(number, table), ksCritical);
    // Mass-weighted: the drawn spheres' mass below each row is the table's F, to 4 standard
    // errors of an r³-weighted fraction (effective sample size (Σw)²/Σw²).
    distribution.weighting = SizeWeighting::mass;
    const std::vector<double> radii = radiiOf(distribution);
    double total = 0, squares = 0;
    for (const double x : radii) {
        total += x * x * x;
        squares += std::pow(x, 6);
    }
    const double effective = total * total / squares;
    for (std::size_t k = 1; k + 1 < r.size(); ++k) {
        double below = 0;
        for (const double x : radii)
            if (x < r[k]) below += x * x * x;
        EXPECT_NEAR(below / total, F[k], 4 * std::sqrt(F[k] * (1 - F[k]) / effective)) << r[k];
    }
    EXPECT_NEAR(RadiusSampler(distribution).meanRadius(), mean(radii),
                4 * standardDeviation(radii) / std::sqrt(double(draws)));
}

// ---- file ----------------------------------------------------------------------------------

TEST(FileInjection, CsvRowsGiveThePositionsVelocitiesSizesAndTimes) {
    test::ScratchDirectory scratch("inject-csv");
    std::ofstream(scratch.path / "constant" / "rows.csv")
        << "# two particles\nx,y,z,u,v,w,d,t\n0.001,0.002,-0.003,10,-1,0.5,1e-4,0\n"
           "0.002 0.001 0 12 0 0 2e-4 2.5e-3\n";
    const Scene scene = sceneOf(scratch, sprayDictionary(R"(
injectors { rows { model file; file "constant/rows.csv"; startTime 1e-3; } }
)",
                                                         0));
    ASSERT_EQ(scene.particles.count, 2);
    const ParticleCloud cloud = injectAll(scene);
    ASSERT_EQ(cloud.size(), 2u);
    EXPECT_TRUE(cloud.position[0] == Vec3(0.001, 0.002, -0.003));
    EXPECT_TRUE(cloud.velocity[0] == Vec3(10, -1, 0.5)); // the row's, not the gas's
    EXPECT_EQ(cloud.radius[0], 5e-5);
    EXPECT_EQ(cloud.radius[1], 1e-4);
    const InjectorSet injectors(scene.injectors);
    EXPECT_EQ(injectors.injectionTime(1), 1e-3 + 2.5e-3);
}

TEST(FileInjection, SpinAndTemperatureColumnsStartTheParticles) {
    test::ScratchDirectory scratch("inject-csv-states");
    std::ofstream(scratch.path / "constant" / "rows.csv")
        << "x y z u v w r wx wy wz T\n0.001 0 0 20 0 0 8e-5 100 -200 300 350\n";
    const std::string rows = "injectors { rows { model file; file \"constant/rows.csv\"; } }\n";
    Scene scene = sceneOf(scratch, sprayDictionary(rows + "physics { spin on; heatTransfer { "
                                                          "model ranzMarshall; } }\n"
                                                          "particles { specificHeat 450; }\n",
                                                   0));
    scene.collisions.model = CollisionModel::none;
    const auto carrier = carrierOf(scene);
    Stepper stepper(scene, *carrier);
    stepper.step();
    // After one step of 10 µs, against relaxation times of 88 ms (spin, Eq. 3.18) and seconds
    // (temperature, Eq. 3.27): the given values to 1e-3.
    const ParticleCloud& cloud = stepper.cloud();
    ASSERT_EQ(cloud.size(), 1u);
    EXPECT_LT((cloud.angularVelocity[0] - Vec3(100, -200, 300)).norm(), 1e-3 * 374);
    EXPECT_NEAR(cloud.temperature[0], 350, 1e-3 * 350);
    // Values the particles could not keep are refused, not dropped.
    try {
        sceneOf(scratch, sprayDictionary(rows, 0));
        ADD_FAILURE() << "accepted";
    } catch (const InputError& error) {
        EXPECT_EQ(error.key(), "injectors.rows.file");
        EXPECT_NE(std::string(error.what()).find("gives spins (wx wy wz)"), std::string::npos);
    }
}

TEST(FileInjection, BadRowsAreInputErrorsNamingFileLineAndColumn) {
    test::ScratchDirectory scratch("inject-csv-bad");
    const auto table = scratch.path / "constant" / "rows.csv";
    const std::string dictionary =
        sprayDictionary("injectors { rows { model file; file \"constant/rows.csv\"; } }\n", 0);
    const auto refusal = [&](const std::string& csv) {
        std::ofstream(table) << csv;
        try {
            sceneOf(scratch, dictionary);
        } catch (const InputError& error) {
            EXPECT_EQ(error.file(), table.string());
            return std::to_string(error.line()) + " " + error.key() + ": " + error.reason();
        }
        return std::string("accepted");
    };
    EXPECT_EQ(refusal("x y z u v w d\n0 0 0 1 1 1 heavy\n"),
              "2 d: expected a finite number, found 'heavy'");
    EXPECT_EQ(refusal("x y z u v w d t\n0 0 0 1 1 1 1e-4 2\n0 0 0 1 1 1 1e-4 1\n"),
              "3 t: goes back in time: rows must be in order of injection time");
    EXPECT_EQ(refusal("x y z u v w diameter\n"),
              "1 diameter: unknown column; columns are x y z u v w d r t wx wy wz T rho");
    EXPECT_EQ(refusal("x y z u v w r\n0 0 0 1 1 1\n"), "2 : 6 values, the header names 7 columns");
    // The command line: one message, exit status 2.
    std::ofstream(table) << "x y z u v w r\n0 0 0 1 1 1 -1\n";
    EXPECT_EQ(test::runCli(scratch.path.string() + " --quiet", scratch.path / "log"), 2);
    EXPECT_NE(
        test::slurp(scratch.path / "log").find("rows.csv:2: key 'r': must be a positive number"),
        std::string::npos)
        << test::slurp(scratch.path / "log");
}

TEST(FileInjection, ChainedRunStartsFromTheArrivalsOfTheFirstBitForBit) {
    test::ScratchDirectory first("inject-chain-a"), second("inject-chain-b");
    std::ofstream(first.path / "constant" / "slidesProperties")
        << sprayDictionary(shorthandInjection, 300);
    ASSERT_EQ(
        test::runCli(first.path.string() + " --quiet --output " + (first.path / "out").string(),
                     first.path / "log"),
        0);
    const Scene scene = sceneOf(
        second, sprayDictionary("injectors { fromA { model file; file \"" +
                                    (first.path / "out" / "particles.h5").string() + "\"; } }\n",
                                0));
    const Hdf5File arrivals(first.path / "out" / "particles.h5", Hdf5Access::readOnly);
    const auto positions = arrivals.readDoubles("/arrivals/position", 3);
    const auto velocities = arrivals.readDoubles("/arrivals/velocity", 3);
    const auto diameters = arrivals.readDoubles("/arrivals/diameter", 1);
    const auto times = arrivals.readDoubles("/arrivals/time", 1);
    ASSERT_EQ(scene.particles.count, 300);
    const ParticleCloud cloud = injectAll(scene);
    ASSERT_EQ(cloud.size(), 300u);
    // The rows in order of arrival time (the file's order within one time).
    std::vector<std::size_t> order(300);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return times[a] < times[b]; });
    const InjectorSet injectors(scene.injectors);
    for (std::size_t i = 0; i < 300; ++i) {
        const std::size_t a = order[i];
        ASSERT_TRUE(cloud.position[i] ==
                    Vec3(positions[3 * a], positions[3 * a + 1], positions[3 * a + 2]));
        ASSERT_TRUE(cloud.velocity[i] ==
                    Vec3(velocities[3 * a], velocities[3 * a + 1], velocities[3 * a + 2]));
        ASSERT_EQ(2 * cloud.radius[i], diameters[a]);
        ASSERT_EQ(injectors.injectionTime(i), times[a]);
    }
}

// ---- chained from a frame; OpenFOAM positions lists ----------------------------------------

// Exact binary times: dt = 2⁻¹⁷ s, the frame at T = 384 dt = 2.93 ms (the spray arrives at the
// target from 2.4 to 3.6 ms), the end at 2T. Every clock reading
// of either run is then an exact multiple of dt, so both take steps of exactly dt. (With a
// decimal dt the clocks round differently: the first run's last step, min(dt, endTime − t),
// would differ from the second's in its last bits, and so would the positions after it.)
constexpr double binaryStep = 0x1p-17, frameTime = 384 * binaryStep;

/// The default spray with drag, buoyancy and gravity only (no per-particle state beyond what a
/// frame holds), in steps of binaryStep until endTime, a frame every frameTime.
std::string plainSpray(const std::string& injection, long count, double endTime) {
    char settings[640];
    std::snprintf(settings, sizeof settings, R"(
physics { history { model none; } addedMass off; pressureGradient off; lift none; spin off;
          dispersion { model none; } heatTransfer { model none; } }
collisions { model none; }
time { dt %.17g; endTime %.17g; stopWhenAllDone no; }
output { interval %.17g; hdf5 yes; carrierResolution (8 4 4); }
)",
                  binaryStep, endTime, frameTime);
    return sprayDictionary(injection, count) + settings;
}

/// Runs the case in scratch to scratch/out; the run's exit status.
int runTo(const test::ScratchDirectory& scratch, const std::string& dictionary) {
    std::ofstream(scratch.path / "constant" / "slidesProperties") << dictionary;
    return test::runCli(scratch.path.string() + " --quiet --output " +
                            (scratch.path / "out").string(),
                        scratch.path / "log");
}

/// A file injector of the given file and fileCoeffs.
std::string fileInjector(const std::string& name, const std::filesystem::path& file,
                         const std::string& coeffs) {
    return "injectors { " + name + " { model file; file \"" + file.string() + "\"; " + coeffs +
           " } }\n";
}

TEST(FileInjection, RunFromAFrameContinuesTheFirstRunBitForBit) {
    test::ScratchDirectory first("inject-frame-a"), second("inject-frame-b");
    ASSERT_EQ(runTo(first, plainSpray("injection { mode allAtStart; crossSpanSpeed 0.5; }\n", 300,
                                      2 * frameTime)),
              0)
        << test::slurp(first.path / "log");
    const auto fromA = first.path / "out" / "particles.h5";
    char time[64];
    std::snprintf(time, sizeof time, "fileCoeffs { source frame; time %.17g; }", frameTime);
    ASSERT_EQ(runTo(second, plainSpray(fileInjector("fromA", fromA, time), 0, frameTime)), 0)
        << test::slurp(second.path / "log");

    const auto summary = nlohmann::json::parse(test::slurp(second.path / "out" / "summary.json"));
    EXPECT_EQ(summary["settings"]["injectors"]["fromA"]["file"],
              nlohmann::json({{"format", "particlesH5"}, {"source", "frame"}, {"frame", 1}}));
    const Hdf5File a(fromA, Hdf5Access::readOnly);
    const Hdf5File b(second.path / "out" / "particles.h5", Hdf5Access::readOnly);
    ASSERT_EQ(a.readDouble("/frames/000001", "time"), frameTime);
    // B's particle k is the k-th in flight in A's frame at T (its arrived ones left out).
    const auto idsAtT = a.readUInt64("/frames/000001/id");
    const auto statesAtT = a.readInt32("/frames/000001/state");
    std::vector<std::uint64_t> inFlight;
    for (std::size_t i = 0; i < idsAtT.size(); ++i)
        if (statesAtT[i] == 0) inFlight.push_back(idsAtT[i]);
    ASSERT_GT(inFlight.size(), 30u);
    ASSERT_LT(inFlight.size(), idsAtT.size() - 30) << "some arrived before T";
    // Both runs' ends: every particle of B where, as fast as, and in the state its original
    // is in A's, bit for bit.
    const auto idsA = a.readUInt64("/frames/000002/id"), idsB = b.readUInt64("/frames/000001/id");
    const auto xA = a.readDoubles("/frames/000002/position", 3),
               xB = b.readDoubles("/frames/000001/position", 3);
    const auto uA = a.readDoubles("/frames/000002/velocity", 3),
               uB = b.readDoubles("/frames/000001/velocity", 3);
    const auto sA = a.readInt32("/frames/000002/state"), sB = b.readInt32("/frames/000001/state");
    std::map<std::uint64_t, std::size_t> rowOfA;
    for (std::size_t i = 0; i < idsA.size(); ++i) rowOfA[idsA[i]] = i;
    const long continued = std::count_if(idsA.begin(), idsA.end(), [&](std::uint64_t id) {
        return std::find(inFlight.begin(), inFlight.end(), id) != inFlight.end();
    });
    ASSERT_EQ(long(idsB.size()), continued);
    long arrivedAfterT = 0;
    for (std::size_t j = 0; j < idsB.size(); ++j) {
        const std::size_t i = rowOfA.at(inFlight.at(idsB[j]));
        for (int c = 0; c < 3; ++c) {
            ASSERT_EQ(xB[3 * j + c], xA[3 * i + c]) << "particle " << idsB[j];
            ASSERT_EQ(uB[3 * j + c], uA[3 * i + c]) << "particle " << idsB[j];
        }
        ASSERT_EQ(sB[j], sA[i]);
        arrivedAfterT += sB[j];
    }
    EXPECT_GT(arrivedAfterT, 0) << "some arrive between T and the end";
    // Their arrivals: the same place and velocity; the time T later, to the rounding of the
    // two sums (the same step start plus the same fraction of a step, added in another order:
    // a few units in the last place of 5.9 ms, 8.7e-19 s).
    const auto arrivalIdsA = a.readUInt64("/arrivals/id"),
               arrivalIdsB = b.readUInt64("/arrivals/id");
    const auto tA = a.readDoubles("/arrivals/time", 1), tB = b.readDoubles("/arrivals/time", 1);
    const auto pA = a.readDoubles("/arrivals/position", 3),
               pB = b.readDoubles("/arrivals/position", 3);
    ASSERT_EQ(long(arrivalIdsB.size()), arrivedAfterT);
    for (std::size_t j = 0; j < arrivalIdsB.size(); ++j) {
        const auto at =
            std::find(arrivalIdsA.begin(), arrivalIdsA.end(), inFlight.at(arrivalIdsB[j]));
        ASSERT_NE(at, arrivalIdsA.end());
        const std::size_t i = std::size_t(at - arrivalIdsA.begin());
        EXPECT_NEAR(tB[j] + frameTime, tA[i], 8 * 8.7e-19);
        for (int c = 0; c < 3; ++c) ASSERT_EQ(pB[3 * j + c], pA[3 * i + c]);
    }
}

/// A particles.h5 by the run's own writer (io/hdf5_particles.h): three particles, the last
/// arrived, with spins and temperatures, in frames at t = 0, 1e-3 (plus one unit in the last
/// place, as a run's clock may give) and 2e-3, and a frame at 3e-3 without diameters.
std::filesystem::path writeFrames(const std::filesystem::path& directory) {
    const std::vector<std::uint64_t> ids{7, 8, 9};
    const std::vector<Vec3> positions{{0.01, 0.001, 0}, {0.02, -0.002, 0.001}, {0.06, 0, 0}};
    const std::vector<Vec3> velocities{{20, 0.5, 0}, {18, -1, 0.25}, {0, 0, 0}};
    const std::vector<double> radii{40e-6, 1.0 / 30000, 80e-6};
    const std::vector<std::int32_t> states{0, 0, 1};
    const std::vector<Vec3> spins{{100, 0, -50}, {0, 30.5, 0}, {0, 0, 0}};
    const std::vector<double> temperatures{350, 400.25, 300};
    ParticlesHdf5 h5(directory, "frames");
    ParticleFrame frame{ids, positions, velocities, radii, states};
    frame.temperature = temperatures;
    frame.angularVelocity = spins;
    for (const double time : {0.0, std::nextafter(1e-3, 1.0), 2e-3}) h5.writeFrame(time, frame);
    frame.fields = ParticleFieldSet::all().without(ParticleField::diameter);
    h5.writeFrame(3e-3, frame);
    h5.finish({});
    return directory / ParticlesHdf5::fileName;
}

TEST(FileInjection, FrameGivesItsParticlesInFlightWithTheStatesTheRunKeeps) {
    test::ScratchDirectory scratch("inject-frame-states");
    const auto frames = writeFrames(scratch.path);
    const std::string fromFrame =
        fileInjector("fromA", frames, "startTime 5e-4; fileCoeffs { source frame; time 1e-3; }");
    const Scene scene = sceneOf(scratch, sprayDictionary(fromFrame + "physics { spin on; "
                                                                     "heatTransfer { model "
                                                                     "ranzMarshall; } }\n"
                                                                     "particles { specificHeat "
                                                                     "450; }\n",
                                                         0));
    ASSERT_EQ(scene.particles.count, 2); // the arrived one left out
    const InjectorSet injectors(scene.injectors);
    EXPECT_EQ(injectors.injectionTime(0), 5e-4); // all at startTime
    EXPECT_EQ(injectors.injectionTime(1), 5e-4);
    ParticleCloud cloud = injectAll(scene);
    ASSERT_EQ(cloud.size(), 2u);
    // The arrays of the states this run keeps (the stepper sizes them so), then the frame's.
    cloud.angularVelocity.resize(2, Vec3::Zero());
    cloud.temperature.resize(2, 0.0);
    injectors.setStartStates(cloud, 0);
    EXPECT_TRUE(cloud.position[1] == Vec3(0.02, -0.002, 0.001));
    EXPECT_TRUE(cloud.velocity[1] == Vec3(18, -1, 0.25));
    EXPECT_EQ(cloud.radius[1], 1.0 / 30000); // 0.5 (2 r): exact
    EXPECT_TRUE(cloud.angularVelocity[1] == Vec3(0, 30.5, 0));
    EXPECT_EQ(cloud.temperature[1], 400.25);
    // A run that keeps neither takes the rest (the CSV's spin and T columns are refused there).
    const Scene plain = sceneOf(scratch, sprayDictionary(fromFrame, 0));
    EXPECT_EQ(plain.particles.count, 2);
}

const std::string foamHeader =
    R"(/*--------------------------------*- C++ -*----------------------------------*\
  =========                 |
  \\      /  F ield         | OpenFOAM: The Open Source CFD Toolbox
\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       vectorField;
    object      kinematicCloudPositions;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

)";

TEST(FileInjection, OpenFoamPositionsListStartsItsParticlesAtU0WithDrawnSizes) {
    test::ScratchDirectory scratch("inject-foam-positions");
    // The length, then positions with none, one and three labels after them (manualInjection's
    // file; a cloud's positions file of v1912, `(x y z) celli`; older ones' tetFace and tetPt).
    std::ofstream(scratch.path / "constant" / "kinematicCloudPositions")
        << foamHeader
        << "3\n(\n(0.001 0 0)\n(0.002 0.0005 0) 117\n(3e-3 -5e-4 1e-3) 117 402 1\n)\n"
           "// ************************************************************************* //\n";
    const std::string sizes = "radiusDistribution { type logNormal; median 20e-6; "
                              "geometricStandardDeviation 1.5; minimum 5e-6; maximum 80e-6; }";
    const Scene scene =
        sceneOf(scratch, sprayDictionary(fileInjector("bed", "constant/kinematicCloudPositions",
                                                      "fileCoeffs { velocity (20 1 0); } " + sizes),
                                         0));
    ASSERT_EQ(scene.particles.count, 3);
    const ParticleCloud cloud = injectAll(scene);
    ASSERT_EQ(cloud.size(), 3u);
    EXPECT_TRUE(cloud.position[1] == Vec3(0.002, 0.0005, 0));
    EXPECT_TRUE(cloud.position[2] == Vec3(3e-3, -5e-4, 1e-3));
    const RadiusSampler drawn(scene.injectors[0].radius);
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_TRUE(cloud.velocity[k] == Vec3(20, 1, 0)); // U0, not the gas's
        EXPECT_EQ(cloud.radius[k], drawn.draw(1, k));     // as a disc's: keyed by (seed, id)
    }
    // Without the length; sizes from particles.radiusDistribution (fixed 80 µm).
    std::ofstream(scratch.path / "constant" / "kinematicCloudPositions")
        << foamHeader << "(\n(0.001 0 0) (0.002 0 0)\n)\n";
    const ParticleCloud fixed = injectAll(
        sceneOf(scratch, sprayDictionary(fileInjector("bed", "constant/kinematicCloudPositions",
                                                      "fileCoeffs { velocity (20 1 0); }"),
                                         0)));
    ASSERT_EQ(fixed.size(), 2u);
    EXPECT_EQ(fixed.radius[1], 80e-6);
    // Binary: the length, then the raw little-endian doubles between the parentheses.
    const std::array<double, 6> raw{0.001, 0, 0, 1.0 / 3000, -1e-4, 0};
    std::string binary = foamHeader;
    binary.replace(binary.find("ascii"), 5, "binary");
    binary += "2\n(";
    binary.append(reinterpret_cast<const char*>(raw.data()), sizeof raw);
    binary += ")\n";
    std::ofstream(scratch.path / "constant" / "kinematicCloudPositions", std::ios::binary)
        << binary;
    const ParticleCloud read = injectAll(
        sceneOf(scratch, sprayDictionary(fileInjector("bed", "constant/kinematicCloudPositions",
                                                      "fileCoeffs { velocity (20 1 0); }"),
                                         0)));
    ASSERT_EQ(read.size(), 2u);
    EXPECT_TRUE(read.position[1] == Vec3(1.0 / 3000, -1e-4, 0));
}

/// Runs the case of dictionary in scratch, which must be refused with exit status 2, one
/// message and no output; returns the message.
std::string refusedRun(const test::ScratchDirectory& scratch, const std::string& dictionary) {
    std::ofstream(scratch.path / "constant" / "slidesProperties") << dictionary;
    const auto log = scratch.path / "log";
    EXPECT_EQ(test::runCli(scratch.path.string() + " --quiet", log), 2);
    const std::string message = test::slurp(log);
    EXPECT_EQ(message.find("error:"), message.rfind("error:")) << "one message: " << message;
    EXPECT_FALSE(std::filesystem::exists(scratch.path / "slides")) << "output written";
    return message;
}

/// The line of the first occurrence of text in dictionary.
int lineOf(const std::string& dictionary, const std::string& text) {
    return 1 + int(std::count(dictionary.begin(), dictionary.begin() + long(dictionary.find(text)),
                              '\n'));
}

TEST(FileInjection, BadFramesAndPositionsListsAreRefusedAtFileLineAndKey) {
    test::ScratchDirectory scratch("inject-file-refusals");
    const auto frames = writeFrames(scratch.path);
    const auto expectRefused = [&](const std::string& injector, const std::string& where,
                                   const std::string& expected) {
        const std::string dictionary = sprayDictionary(injector, 0);
        const std::string message = refusedRun(scratch, dictionary);
        const std::string located =
            where.empty()
                ? expected
                : "slidesProperties:" + std::to_string(lineOf(dictionary, where)) + ": " + expected;
        EXPECT_NE(message.find(located), std::string::npos) << "expected '" << located << "' in:\n"
                                                            << message;
    };
    // A time that matches no frame: the frames' times listed.
    expectRefused(fileInjector("fromA", frames, "fileCoeffs {\nsource frame;\ntime 1.5e-3; }"),
                  "time 1.5e-3",
                  "key 'injectors.fromA.fileCoeffs.time': no frame of " + frames.string() +
                      " at t = 0.0015 s; its 4 frames are at 0 0.001 0.002 0.003 s");
    expectRefused(fileInjector("fromA", frames, "fileCoeffs {\nsource frame;\ntime 3e-3; }"), "",
                  frames.string() +
                      ": key '/frames/000003/diameter': missing: the run wrote its frames "
                      "without diameter (output.fields)");
    expectRefused(fileInjector("fromA", frames, "fileCoeffs {\nsource frame; }"), "fileCoeffs {",
                  "key 'injectors.fromA.fileCoeffs.time': missing key (s), needed for source "
                  "frame");
    expectRefused(fileInjector("rows", "constant/missing.csv", ""), "missing.csv",
                  "key 'injectors.rows.file': no file " +
                      (scratch.path / "constant" / "missing.csv").string());
    // Keys where they do not apply.
    std::ofstream(scratch.path / "constant" / "rows.csv")
        << "x y z u v w d\n0.001 0 0 1 0 0 1e-4\n";
    expectRefused(fileInjector("rows", "constant/rows.csv", "fileCoeffs {\nsource frame; }"),
                  "source frame",
                  "key 'injectors.rows.fileCoeffs.source': only a previous run's particles.h5 "
                  "has arrivals and frames");
    expectRefused(fileInjector("fromA", frames, "fileCoeffs {\ntime 1e-3; }"), "time 1e-3",
                  "key 'injectors.fromA.fileCoeffs.time': only source frame (of a particles.h5) "
                  "takes a frame's time");
    expectRefused(fileInjector("fromA", frames, "fileCoeffs {\nvelocity (1 0 0); }"),
                  "velocity (1 0 0)",
                  "key 'injectors.fromA.fileCoeffs.velocity': only an OpenFOAM positions list "
                  "takes a velocity");
    // Positions lists: a malformed entry, a length that differs from the entries, no velocity,
    // a position outside the domain box (checked as a CSV's rows are).
    const auto list = scratch.path / "constant" / "kinematicCloudPositions";
    const std::string bed = fileInjector("bed", "constant/kinematicCloudPositions",
                                         "fileCoeffs {\nvelocity (20 0 0); }");
    const int header = int(std::count(foamHeader.begin(), foamHeader.end(), '\n'));
    const int firstEntry = header + 3; // after the header, the length and "("
    std::ofstream(list) << foamHeader << "2\n(\n(0.001 0 0)\n(0.002 0 O)\n)\n";
    expectRefused(bed, "",
                  list.string() + ":" + std::to_string(firstEntry + 1) +
                      ": key 'injectors.bed.file': entry 2: expected a number, found 'O'");
    std::ofstream(list) << foamHeader << "2\n(\n(0.001 0 0)\n(0.002 0 0 1e-3)\n)\n";
    expectRefused(bed, "",
                  list.string() + ":" + std::to_string(firstEntry + 1) +
                      ": key 'injectors.bed.file': entry 2: a position has 3 coordinates, this "
                      "has 4");
    std::ofstream(list) << foamHeader << "3\n(\n(0.001 0 0)\n(0.002 0 0)\n)\n";
    expectRefused(bed, "",
                  list.string() + ":" + std::to_string(header + 1) +
                      ": key 'injectors.bed.file': the list announces 3 positions and holds 2");
    std::ofstream(list) << foamHeader << "(\n(0.001 0 0)\n(0.2 0 0)\n)\n";
    expectRefused(fileInjector("bed", "constant/kinematicCloudPositions", "fileCoeffs {\n}"),
                  "fileCoeffs {", "key 'injectors.bed.fileCoeffs.velocity': missing key (m/s)");
    expectRefused(bed, "file \"constant",
                  "key 'injectors.bed.file': the 2 particles of the file is not inside the "
                  "domain box: 50 % of it (1 of 2 points");
}

// ---- Chung & Ooi (2011) test 4 from a dictionary ---------------------------------------------

/// Test 4's impact (aluminium oxide, R = 2.5 mm, 3.9 m/s, μ = 0.092, e = 0.98, rigid wall x = 0)
/// as a case: a one-row file injection, soft spheres, a rebounding plane. The sphere's state
/// after the contact, from the run's last frame.
struct ObliqueRun {
    Vec3 velocity, spin;
};

ObliqueRun obliqueImpactCase(double incidenceDegrees, double stepsPerContact) {
    const double radius = 2.5e-3, speed = 3.9, E = 3.8e11, nu = 0.23, density = 4000;
    const double angle = incidenceDegrees * degree;
    const double vn = speed * std::cos(angle), vt = speed * std::sin(angle);
    const double mass = sphereMass(radius, density);
    const ContactPair pair = sphereWallPair({E, nu}, radius, mass, rigidMaterial());
    const double contact = hertzContactDuration(pair, vn);
    const double gap = 1e-3 * radius;
    test::ScratchDirectory scratch("inject-chung-ooi-" + std::to_string(int(incidenceDegrees)));
    char text[2048];
    std::snprintf(text, sizeof text, "x y z u v w r\n%.17g 0 0 %.17g %.17g 0 %.17g\n",
                  -radius - gap, vn, vt, radius);
    std::ofstream(scratch.path / "constant" / "ball.csv") << text;
    std::snprintf(text, sizeof text, R"(
carrier { type none; }
particles { density %.17g; radiusDistribution { type fixed; value %.17g; }
            material { bulkModulus %.17g; shearModulus %.17g; } }
injectors { ball { model file; file "constant/ball.csv"; } }
collisions { model softSphere; restitution { model constant; coefficient 0.98; }
             friction { static 0.092; dynamic 0.092; } }
time { dt %.17g; endTime %.17g; stopWhenAllDone no; }
surfaces { wall { type plane; point (0 0 0); normal (-1 0 0); interaction rebound;
                  material { bulkModulus 1e150; shearModulus 1e150; } } }
domain { min (-0.05 -0.05 -0.05); max (0.01 0.05 0.05); }
output { interval 1; hdf5 yes; }
)",
                  density, radius, E / (3 * (1 - 2 * nu)), E / (2 * (1 + nu)),
                  contact / stepsPerContact, gap / vn + 2 * contact);
    std::ofstream(scratch.path / "constant" / "slidesProperties") << text;
    const auto output = scratch.path / "out";
    const int status = test::runCli(scratch.path.string() + " --quiet --output " + output.string(),
                                    scratch.path / "log");
    EXPECT_EQ(status, 0) << test::slurp(scratch.path / "log");
    const Hdf5File h5(output / "particles.h5", Hdf5Access::readOnly);
    const auto v = h5.readDoubles("/frames/000001/velocity", 3);
    const auto w = h5.readDoubles("/frames/000001/angularVelocity", 3);
    if (v.size() != 3 || w.size() != 3) return {};
    return {Vec3(v[0], v[1], v[2]), Vec3(w[0], w[1], w[2])};
}

class ObliqueImpactFromDictionary : public testing::TestWithParam<double> {};

TEST_P(ObliqueImpactFromDictionary, ReboundAsTheDriverOfTestFour) {
    // The numbers of test_soft_contact.cpp's ObliqueWallImpact (aluminium oxide).
    const double radius = 2.5e-3, speed = 3.9, friction = 0.092;
    const double angle = GetParam() * degree;
    const double vn = speed * std::cos(angle), vt = speed * std::sin(angle);
    const ObliqueRun run = obliqueImpactCase(GetParam(), 200);
    const double en = -run.velocity.x() / vn, et = run.velocity.y() / vt, spin = run.spin.z();
    EXPECT_GT(en, 0.97); // e = 0.98 to first order in the step
    EXPECT_LT(en, 0.99);
    const ContactPair pair =
        sphereWallPair({3.8e11, 0.23}, radius, sphereMass(radius, 4000), rigidMaterial());
    const double leverShortening = hertzMaxOverlap(pair, vn) / radius;
    const double leverRatio = -0.4 * radius * spin / (vt - run.velocity.y());
    EXPECT_LE(leverRatio, 1 + 1e-9);
    EXPECT_GE(leverRatio, 1 - leverShortening);
    const double slidingImpulse = friction * (1 + en) * vn;
    if (vt > 3.5 * slidingImpulse * 1.1) { // gross sliding: the rigid-body result
        EXPECT_NEAR(et, 1 - slidingImpulse / vt, 1e-4);
        EXPECT_NEAR(-spin * radius / (2.5 * slidingImpulse), 1.0,
                    leverShortening + 1e-4 * vt / slidingImpulse);
    } else { // stick–slip: against 1600 steps per contact, as the driver's test
        const ObliqueRun fine = obliqueImpactCase(GetParam(), 1600);
        EXPECT_NEAR(et, fine.velocity.y() / vt, 5e-4);
        EXPECT_NEAR(spin / fine.spin.z(), 1.0, 5e-3);
    }
}

INSTANTIATE_TEST_SUITE_P(ChungOoiTest4, ObliqueImpactFromDictionary,
                         testing::Values(10.0, 30.0, 60.0, 85.0),
                         [](const testing::TestParamInfo<double>& info) {
                             return std::to_string(int(info.param)) + "deg";
                         });

} // namespace
} // namespace slides
