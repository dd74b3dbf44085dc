// ctest-labels: foundation run
// Whole runs: reproducibility (same seed → identical particles; thread count changes nothing),
// conservation of particle count, injection statistics, and the command line's behaviour on
// the default case and on broken cases (exit status 2, one message naming file, line, key).
#include "../support/broken_cases.h"
#include "../support/case_runs.h"
#include "../support/test_scenes.h"
#include "slides/config/scene_keys.h"
#include "slides/config/scene_reader.h"
#include "slides/integrate/injector.h"
#include "slides/run/stepper.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <omp.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace slides {
namespace {

using test::defaultCase;
using test::runCli;
using test::ScratchDirectory;
using test::slurp;
using test::sourceDir;

struct Finished {
    std::vector<ParticleId> ids;
    std::vector<Vec3> positions, velocities;
    long escaped;
    std::size_t arrived;
};

/// The default case shortened to 600 particles, run to the end; state sorted by id.
Finished runDefaultCase(int threads, std::uint64_t seed) {
    Scene scene = readScene(defaultCase);
    scene.particles.count = 600;
    scene.injection.seed = seed;
    scene.time.endTime = 2e-3; // particles still in flight, some arrived
    const auto carrier = test::carrierOf(scene);
    omp_set_num_threads(threads);
    Stepper stepper(scene, *carrier);
    while (!stepper.finished()) stepper.step();
    Finished result{{}, {}, {}, stepper.escaped(), stepper.arrivals().size()};
    const ParticleCloud& cloud = stepper.cloud();
    std::vector<std::size_t> order(cloud.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](auto a, auto b) { return cloud.id[a] < cloud.id[b]; });
    for (auto i : order) {
        result.ids.push_back(cloud.id[i]);
        result.positions.push_back(cloud.position[i]);
        result.velocities.push_back(cloud.velocity[i]);
    }
    EXPECT_EQ(stepper.injected(),
              static_cast<long>(cloud.size() + stepper.arrivals().size()) + stepper.escaped())
        << "particles must be conserved: injected = moving + arrived + escaped";
    return result;
}

TEST(Reproducibility, SameSeedAndAnyThreadCountGiveBitIdenticalParticles) {
    const Finished one = runDefaultCase(1, 7);
    const Finished two = runDefaultCase(2, 7);
    ASSERT_FALSE(one.ids.empty());
    ASSERT_EQ(one.ids, two.ids);
    EXPECT_EQ(one.escaped, two.escaped);
    EXPECT_EQ(one.arrived, two.arrived);
    for (std::size_t i = 0; i < one.ids.size(); ++i) {
        ASSERT_EQ(one.positions[i], two.positions[i]) << "particle " << one.ids[i];
        ASSERT_EQ(one.velocities[i], two.velocities[i]) << "particle " << one.ids[i];
    }
    const Finished other = runDefaultCase(2, 8);
    EXPECT_NE(one.positions.front(), other.positions.front()) << "the seed must matter";
}

TEST(Injection, RadiiFollowTheNormalDistribution) {
    // 20000 draws: the sample mean has standard error σ/√n = 0.007σ, so ±0.03σ is 4 errors.
    RadiusDistribution distribution;
    distribution.kind = RadiusDistributionKind::normal;
    distribution.mean = 80e-6;
    distribution.standardDeviation = 10e-6;
    distribution.maximum = INFINITY;
    double sum = 0, squares = 0;
    const int n = 20000;
    for (int id = 0; id < n; ++id) {
        const double radius = drawRadius(distribution, 3, static_cast<ParticleId>(id));
        sum += radius;
        squares += radius * radius;
    }
    const double mean = sum / n;
    const double deviation = std::sqrt(squares / n - mean * mean);
    EXPECT_NEAR(mean, 80e-6, 0.03 * 10e-6);
    EXPECT_NEAR(deviation, 10e-6, 0.03 * 10e-6); // standard error of σ̂: σ/√(2n) = 0.005σ
}

TEST(Injection, LogNormalMedianAndTruncation) {
    RadiusDistribution distribution;
    distribution.kind = RadiusDistributionKind::logNormal;
    distribution.median = 50e-6;
    distribution.geometricStandardDeviation = 1.5;
    distribution.minimum = 30e-6;
    distribution.maximum = 90e-6;
    std::vector<double> radii;
    for (int id = 0; id < 10001; ++id)
        radii.push_back(drawRadius(distribution, 5, static_cast<ParticleId>(id)));
    for (double radius : radii) ASSERT_TRUE(radius > 30e-6 && radius < 90e-6);
    std::nth_element(radii.begin(), radii.begin() + 5000, radii.end());
    // Truncation at ±1.26σ and ±1.45σ in ln R shifts the median by < 2 %; sampling error ~1 %.
    EXPECT_NEAR(radii[5000] / 50e-6, 1.0, 0.04);
}

TEST(Injection, StartsOnTheNozzleDiscWithGasPlusCrossSpanVelocity) {
    Scene scene = readScene(defaultCase);
    scene.injection.mode = InjectionMode::allAtStart;
    const auto carrier = test::carrierOf(scene);
    Injector injector(scene.injection, scene.nozzle, scene.particles);
    ParticleCloud cloud;
    injector.injectUntil(0.0 + 1e-12, 0.0, *carrier, cloud);
    ASSERT_EQ(static_cast<long>(cloud.size()), scene.particles.count);
    CarrierSample gas;
    carrier->sample(cloud.position, 0.0, {}, gas);
    double radialSum = 0;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const Vec3 offset = cloud.position[i] - scene.nozzle.centre;
        ASSERT_NEAR(offset.dot(scene.nozzle.axis), 0.0, 1e-15);
        ASSERT_LE(offset.norm(), scene.nozzle.radius * (1 + 1e-12));
        radialSum += offset.norm();
        const Vec3 slip = cloud.velocity[i] - gas.velocity[i];
        ASSERT_NEAR(slip.norm(), scene.injection.crossSpanSpeed, 1e-12);
        ASSERT_NEAR(slip.dot(scene.nozzle.axis), 0.0, 1e-12);
    }
    // Uniform in area: mean distance from the centre is 2R/3 (standard error 0.24R/√8000).
    EXPECT_NEAR(radialSum / cloud.size() / scene.nozzle.radius, 2.0 / 3.0, 0.012);
}

class InjectionTiming : public ::testing::TestWithParam<IntegratorName> {};

TEST_P(InjectionTiming, ParticlesDueInsideAStepFlyOnlyItsRemainder) {
    // In a uniform stream U, particle k enters at t_k = k/rate with v = U (no slip, no force),
    // so x_k(t) = centre + U (t − t_k) exactly, and it touches a plane at distance L (with its
    // radius R) at t_k + (L − R)/|U|: exact for every integrator, whatever dt, if a particle due
    // inside a step flies only the rest of that step. dt = 3.7 ms is not a multiple of 1/rate.
    Scene scene = test::singleParticleScene();
    scene.time.integrator = GetParam().value;
    scene.particles.count = 40;
    scene.injection.mode = InjectionMode::rate;
    scene.injection.rate = 1000;
    scene.time.dt = 3.7e-3;
    scene.time.endTime = 0.05;
    const Vec3 stream(10, 0, 0);
    const double standoff = 0.3, radius = scene.particles.radius.value;
    scene.surfaces.push_back(
        {"target", Vec3(standoff, 0, 0), Vec3(-1, 0, 0), {}, SurfaceInteraction::absorb, "", {}});
    const test::UniformFlow flow(stream);
    Stepper stepper(scene, flow);
    while (!stepper.finished()) stepper.step();

    const double t = stepper.time();
    ASSERT_GT(stepper.cloud().size(), 10u);
    for (std::size_t i = 0; i < stepper.cloud().size(); ++i) {
        const double entered = static_cast<double>(stepper.cloud().id[i]) / scene.injection.rate;
        EXPECT_NEAR(stepper.cloud().position[i].x(), stream.x() * (t - entered), 1e-14)
            << "particle " << stepper.cloud().id[i];
    }
    ASSERT_GT(stepper.arrivals().size(), 10u);
    for (const Arrival& arrival : stepper.arrivals()) {
        const double entered = static_cast<double>(arrival.id) / scene.injection.rate;
        EXPECT_NEAR(arrival.time, entered + (standoff - radius) / stream.x(), 1e-15)
            << "particle " << arrival.id;
    }
}

INSTANTIATE_TEST_SUITE_P(Integrators, InjectionTiming, ::testing::ValuesIn(integratorNames()),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(CommandLine, RunsTheDefaultCaseAndWritesEveryOutput) {
    ScratchDirectory scratch("default-run");
    const auto output = scratch.path / "out";
    ASSERT_EQ(
        runCli(defaultCase.string() + " --quiet --output " + output.string(), scratch.path / "log"),
        0)
        << slurp(scratch.path / "log");
    for (const char* file : {"particles.pvd", "carrier.vti", "summary.json", "particles_000000.vtp",
                             "particles.h5", "particles.xmf"})
        EXPECT_TRUE(std::filesystem::exists(output / file)) << file;
    const auto summary = nlohmann::json::parse(slurp(output / "summary.json"));
    const long injected = summary["particles"]["injected"];
    EXPECT_EQ(injected, 8000);
    const long arrived = summary["particles"]["arrived"]["target"];
    const long escaped = summary["particles"]["escaped"];
    const long active = summary["particles"]["active"];
    EXPECT_EQ(arrived + escaped + active, injected);
    EXPECT_EQ(active, 0) << "stopWhenAllDone: the run ends when every particle is done";
    EXPECT_GT(arrived, 7900) << "heavy particles fly nearly straight onto the target";
    // No gas is faster than U0 = 25 m/s (the jet's centreline maximum) and the particles start
    // at the gas velocity, so none can touch the plate (standoff 0.06 m, radius 80 µm) before
    // (0.06 − 80e-6)/25 s, nor arrive faster than U0 plus the cross-span and gravity parts;
    // with τ_St = 0.29 s ≫ the flight time, they keep most of their speed. The spray is dense
    // (volume fraction 0.5 % at the nozzle): the scene analysis turns collisions on, and they
    // conserve momentum and lose energy, so the arrivals' kinetic energy (rms speed) keeps
    // that bound, though one particle may leave a collision faster than it came.
    const auto& arrivals = summary["arrivals"]["target"];
    EXPECT_EQ(arrivals["count"].get<long>(), arrived);
    EXPECT_GE(arrivals["arrivalTime"]["min"].get<double>(), (0.06 - 80e-6) / 25);
    const double flight = arrivals["arrivalTime"]["max"]; // gravity acts ⟂ axis meanwhile
    const double fastest = std::hypot(25.0, 0.5 + 9.81 * flight);
    const auto& terms = summary["sceneAnalysis"]["terms"];
    const auto collisions = std::find_if(
        terms.begin(), terms.end(), [](const auto& term) { return term["term"] == "collisions"; });
    ASSERT_NE(collisions, terms.end());
    EXPECT_EQ((*collisions)["decision"], "on");
    EXPECT_GT(summary["collisions"]["particlePairs"].get<long>(), 0);
    EXPECT_GT(arrivals["impactNormalSpeed"]["mean"].get<double>(), 0.5 * 25);
    const double mean = arrivals["impactSpeed"]["mean"];
    const double deviation = arrivals["impactSpeed"]["standardDeviation"];
    const double rms = arrivals["impactSpeed"]["rms"];
    EXPECT_LE(rms, fastest);
    EXPECT_NEAR(rms * rms, mean * mean + deviation * deviation, 1e-12 * rms * rms);
    EXPECT_GT(deviation, 0.0) << "particles across the nozzle start at different gas speeds";
    EXPECT_GT(summary["performance"]["particleStepsPerSecond"].get<double>(), 0);
    for (const auto& entry : std::filesystem::directory_iterator(output))
        EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos)
            << "temporary left behind: " << entry.path();
}

const test::BrokenCase brokenCases[] = {
    {"unknownKey", "    density     5680;", "    density     5680;\n    densty 1;", 1,
     "key 'particles.densty': unknown key; valid keys here are:"},
    {"wrongType", "    count       8000;", "    count       many;", 0,
     "key 'particles.count': expected"},
    {"negativeRadius", "        value   80e-6;", "        value   -80e-6;", 0,
     "key 'particles.radiusDistribution.value': must be a positive number"},
    {"unknownModel", "    drag        haiderLevenspiel;", "    drag        fast;", 0,
     "key 'physics.drag': unknown drag 'fast'; valid drag names are:"},
    {"missingSemicolon", "    seed            1;", "    seed            1", 0,
     "key 'injection.seed': missing ';' at the end of the entry"},
    {"unknownOutputField", "    interval            5e-4;",
     "    interval            5e-4;\n    fields (id speed pressure);", 1,
     "key 'output.fields': unknown fields 'pressure'; valid fields names are:"},
    {"spinOutputWithoutSpin", "    interval            5e-4;",
     "    interval            5e-4;\n    fields (id angularVelocity);\n}\n"
     "physics { spin off; lift none; }\nsurfaces { target { type plane; point (0.05 0 0); "
     "normal (-1 0 0); interaction absorb; } }\noutput {",
     1, "key 'output.fields': angularVelocity needs the particles' spin"},
    {"nozzleOutsideDomain", "    centre      (0 0 0);", "    centre      (1 0 0);", 0,
     "key 'nozzle.centre': lies outside the domain box"},
    {"softSphereWithVelocityDependentRestitution", "    buoyancy    on;\n}\n",
     "    buoyancy    on;\n}\ncollisions { model softSphere; restitution { model "
     "velocityDependent; } }\n",
     2, "key 'collisions.restitution.model': must be constant for collisions.model softSphere"},
    {"gasTermWithoutGas", "    dt              1e-5;",
     "    dt              1e-5;\n}\ncarrier { type none; }\nphysics { addedMass on; }\ntime {", 3,
     "key 'physics.addedMass': needs a carrier gas, and carrier.type is none"},
    {"electromagneticWithUnsteadyForces", "    buoyancy    on;\n}\n",
     "    buoyancy    on;\n    addedMass   on;\n    electromagnetic { model lorentz; }\n}\n", 2,
     "key 'physics.electromagnetic.model': the Lorentz step does not take the unsteady forces"},
    {"coulombCutoffNotPositive", "    gravity     (0 -9.81 0);",
     "    gravity     (0 -9.81 0);\n"
     "    electromagnetic { model lorentz; coulomb { model shifted; cutoff 0; } }",
     1, "key 'physics.electromagnetic.coulomb.cutoff': must be a positive number"},
    {"coulombWithoutCharges", "    gravity     (0 -9.81 0);",
     "    gravity     (0 -9.81 0);\n    electromagnetic { coulomb { model shifted; } }", 1,
     "key 'physics.electromagnetic.coulomb.model': Coulomb forces act between charged "
     "particles, which physics.electromagnetic.model lorentz gives"},
    {"magnetisationWithoutCoils", "    gravity     (0 -9.81 0);",
     "    gravity     (0 -9.81 0);\n"
     "    electromagnetic { model lorentz; B (0 0 1); magnetisation { model linear; "
     "susceptibility 0.5; } }",
     1,
     "key 'physics.electromagnetic.magnetisation.model': a uniform B pulls no magnetisable "
     "particle"},
    {"coilsWithoutTheLorentzStep", "    gravity     (0 -9.81 0);",
     "    gravity     (0 -9.81 0);\n"
     "    electromagnetic { coils { a { radius 0.05; current 100; } } }",
     1,
     "key 'physics.electromagnetic.coils': the fields act through "
     "physics.electromagnetic.model lorentz"},
    {"susceptibilityOfNoMaterial", "    gravity     (0 -9.81 0);",
     "    gravity     (0 -9.81 0);\n"
     "    electromagnetic { model lorentz; coils { a { radius 0.05; current 100; } }\n"
     "        magnetisation { model linear; susceptibility -1; } }",
     2, "key 'physics.electromagnetic.magnetisation.susceptibility': must be above −1"},
    {"susceptibilityWithoutMagnetisation", "    gravity     (0 -9.81 0);",
     "    gravity     (0 -9.81 0);\n"
     "    electromagnetic { model lorentz; magnetisation { susceptibility 0.5; } }",
     1,
     "key 'physics.electromagnetic.magnetisation.susceptibility': acts with "
     "physics.electromagnetic.magnetisation.model linear"},
    {"coilsWithAdaptiveRungeKutta", "    integrator      exponentialMidpoint;",
     "    integrator      adaptiveRungeKutta;\n}\n"
     "physics { electromagnetic { model lorentz; coils { a { radius 0.05; current 100; } } } }\n"
     "time {",
     0, "key 'time.integrator': the coils' fields vary along a step"},
    {"latticeOfTooFewSites", "    mode            rate;",
     "    mode            lattice;\n    latticeCoeffs { spacing 1e-3; sites (10 10 10); }", 1,
     "key 'injection.latticeCoeffs.sites': hold fewer sites than particles.count"},
};

using test::RefusedCase;
INSTANTIATE_TEST_SUITE_P(CommandLineRejects, RefusedCase, ::testing::ValuesIn(brokenCases),
                         test::brokenCaseName);

TEST(CommandLine, MissingDictionaryIsAnInputError) {
    ScratchDirectory scratch("missing");
    const auto log = scratch.path / "log";
    EXPECT_EQ(runCli(scratch.path.string() + " --quiet", log), 2);
    EXPECT_NE(slurp(log).find("constant/slidesProperties"), std::string::npos) << slurp(log);
}

TEST(KeyTable, ReadmeListsEveryKeyAsDeclared) {
    // The README table is the output of `slides-track --list-keys`; regenerate it with
    // tools/update-readme-keys when keys change.
    EXPECT_NE(slurp(sourceDir / "README.md").find(sceneKeysMarkdown()), std::string::npos)
        << "README.md's key table is out of date: run tools/update-readme-keys";
}

} // namespace
} // namespace slides
