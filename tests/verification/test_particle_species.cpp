// ctest-labels: injection
// Particle species (integrate/injection_settings.h): injectors whose particles differ in density
// or material (`injectors.NAME.density`, `.material {}`, `.specificHeat`). Injectors that all
// give the particles' own values run bit for bit as the case without them; two densities settle
// each at its own Stokes law; a head-on impulse impact of two densities conserves momentum (and
// with e = 1 kinetic energy) to round-off; a Hertz contact of two materials lasts as Hertz's
// closed form with the combined E* and m*; a checkpoint of two species restarts to the same
// bits; the SIMD relaxation with per-particle densities matches the scalar reference lane by
// lane; under the Maxey–Riley terms, adaptiveRungeKutta, eddy-interaction dispersion, heat
// transfer, electromagnetic fields and magnetisation (each its own susceptibility) each particle
// of a two-species run moves (and heats) bit
// for bit as in a run of its species alone; each species heats at its own lumped exponential and
// each density gyrates on its own Larmor circle; Coulomb kicks of two densities conserve
// momentum; every model accepts differing species. A file injector's densities per row (a CSV's
// rho column, a previous run's density): each row settles at its own Stokes law, rows of the
// particles' own density run bit for bit as without the column, a checkpoint restarts to the
// same bits, frames and arrivals carry each one's density, a chained run takes them (from the
// arrivals or a frame), and bad values and what they cannot go with are refused.
#include "../support/case_runs.h"
#include "../support/gas_scenes.h"
#include "../support/test_scenes.h"
#include "slides/carrier/no_gas.h"
#include "slides/config/scene_reader.h"
#include "slides/core/error.h"
#include "slides/integrate/integrator.h"
#include "slides/integrate/relaxation_batch.h"
#include "slides/io/checkpoint.h"
#include "slides/io/hdf5_file.h"
#include "slides/io/hdf5_particles.h"
#include "slides/physics/contact_pair.h"
#include "slides/physics/drag.h"
#include "slides/physics/heat_transfer.h"
#include "slides/run/stepper.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <numbers>
#include <numeric>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace slides {
namespace {

/// A case dictionary in a scratch directory, read as the command line reads it.
Scene sceneOf(const test::ScratchDirectory& scratch, const std::string& text) {
    std::ofstream(scratch.path / "constant" / "slidesProperties") << text;
    return readScene(scratch.path);
}

/// The default case's dictionary with `injection {}` replaced by text (and its count removed).
std::string sprayDictionary(const std::string& injection) {
    std::string text = test::slurp(test::defaultCase / "constant" / "slidesProperties");
    const auto count = text.find("count       8000;");
    text.erase(count, std::string("count       8000;").size());
    const auto start = text.find("injection\n{");
    const auto end = text.find("}\n", start) + 2;
    text.replace(start, end - start, injection);
    return text;
}

/// Two guns into the default case's jet; `a` and `b` go into the injectors' entries.
std::string twoGuns(const std::string& a, const std::string& b,
                    const std::string& collisions = "none") {
    return sprayDictionary(R"(
injectors
{
    upper { model cone; centre (0 0.001 0); axis (1 0 0); radius 0; count 300; rate 1e5;
            coneCoeffs { outerHalfAngle 5; speed 20; } )" +
                           a + R"( }
    lower { model disc; centre (0 -0.0005 0); axis (1 0 0); radius 1e-3; count 500;
            duration 2e-3; crossSpanSpeed 0.5; radiusDistribution { type fixed; value 40e-6; } )" +
                           b + R"( }
}
collisions { model )" + collisions +
                           "; }\n");
}

void expectSameBits(const Stepper& p, const Stepper& q) {
    ASSERT_EQ(p.arrivals().size(), q.arrivals().size());
    for (std::size_t k = 0; k < p.arrivals().size(); ++k) {
        ASSERT_EQ(p.arrivals()[k].id, q.arrivals()[k].id);
        ASSERT_EQ(p.arrivals()[k].time, q.arrivals()[k].time);
        ASSERT_TRUE(p.arrivals()[k].position == q.arrivals()[k].position);
        ASSERT_TRUE(p.arrivals()[k].velocity == q.arrivals()[k].velocity);
    }
    ASSERT_EQ(p.cloud().size(), q.cloud().size());
    for (std::size_t i = 0; i < p.cloud().size(); ++i) {
        ASSERT_EQ(p.cloud().id[i], q.cloud().id[i]);
        ASSERT_TRUE(p.cloud().position[i] == q.cloud().position[i]) << p.cloud().id[i];
        ASSERT_TRUE(p.cloud().velocity[i] == q.cloud().velocity[i]) << p.cloud().id[i];
    }
}

TEST(ParticleSpecies, InjectorsGivingTheParticlesOwnValuesRunBitForBitAsWithoutThem) {
    // Regression guard: the same density and material given per injector leave one species,
    // and the run (impulse collisions on: masses and moduli per particle) is the same bits.
    test::ScratchDirectory a("species-plain"), b("species-same");
    const std::string same = "density 5680; material { bulkModulus 167e9; shearModulus 77e9; }";
    Scene plain = sceneOf(a, twoGuns("", "", "impulse"));
    Scene given = sceneOf(b, twoGuns(same, same, "impulse"));
    ASSERT_TRUE(given.particles.alike());
    for (Scene* scene : {&plain, &given}) scene->time.endTime = 6e-3;
    const auto carrier = carrierOf(plain);
    Stepper first(plain, *carrier), second(given, *carrier);
    while (!first.finished()) first.step();
    while (!second.finished()) second.step();
    EXPECT_GT(first.collisions(), 0);
    EXPECT_EQ(first.collisions(), second.collisions());
    ASSERT_GT(first.arrivals().size(), 100u);
    expectSameBits(first, second);

    // Injectors that all give one other density: one species, theirs.
    test::ScratchDirectory c("species-other");
    const Scene other = sceneOf(c, twoGuns("density 3000;", "density 3000;"));
    EXPECT_TRUE(other.particles.alike());
    EXPECT_EQ(other.particles.density, 3000);
}

/// The particles of scene, particle id at rest at (0, 0.01 id, 0) with density densities[id],
/// in still gas under Stokes drag, gravity and buoyancy: after 500 steps of 1 ms each where and
/// as fast as its own Stokes law has it, for both exponential integrators.
void expectEachSettlesAtItsOwnStokesLaw(Scene scene, const std::vector<double>& densities) {
    scene.physics.drag = DragModel::stokes;
    scene.collisions.model = CollisionModel::none;
    scene.surfaces.clear();
    scene.domain = {Vec3::Constant(-1e6), Vec3::Constant(1e6)};
    scene.time.dt = 1e-3;
    scene.time.endTime = 1.0;
    scene.time.stopWhenAllDone = false;
    const Vec3 g = scene.physics.gravity;
    const test::UniformFlow still(Vec3::Zero());
    for (const Integrator integrator :
         {Integrator::exponentialEuler, Integrator::exponentialMidpoint}) {
        scene.time.integrator = integrator;
        Stepper stepper(scene, still);
        for (int n = 0; n < 500; ++n) stepper.step();
        const double t = stepper.time();
        const ParticleCloud& cloud = stepper.cloud();
        ASSERT_EQ(cloud.size(), densities.size());
        double slowest = 1e300, fastest = 0;
        for (std::size_t i = 0; i < cloud.size(); ++i) {
            // τ = 2 ρp R²/(9 ρf ν); v(t) = v_t (1 − e^(−t/τ)), v_t = τ (1 − ρf/ρp) g;
            // y(t) − y(0) = v_t (t − τ (1 − e^(−t/τ))). Exact for the exponential schemes: the
            // tolerance is round-off over 500 steps.
            const double rho = densities.at(cloud.id[i]);
            const double tau = 2 * rho * cloud.radius[i] * cloud.radius[i] /
                               (9 * scene.fluid.density * scene.fluid.kinematicViscosity);
            const Vec3 terminal = tau * (1 - scene.fluid.density / rho) * g;
            const double decayed = -std::expm1(-t / tau);
            const Vec3 velocity = terminal * decayed;
            const Vec3 start(0, 0.01 * double(cloud.id[i]), 0);
            const Vec3 drop = terminal * (t - tau * decayed);
            EXPECT_NEAR(cloud.velocity[i].y(), velocity.y(), 1e-12 * std::abs(velocity.y()))
                << "ρp " << rho;
            EXPECT_NEAR((cloud.position[i] - start).y(), drop.y(), 1e-12 * std::abs(drop.y()))
                << "ρp " << rho;
            slowest = std::min(slowest, std::abs(cloud.velocity[i].y()));
            fastest = std::max(fastest, std::abs(cloud.velocity[i].y()));
        }
        // The densities really differ: τ ∝ ρp (8000 against 1000: 5.6 times as fast at 0.5 s).
        EXPECT_GT(fastest, 5 * slowest);
    }
}

/// Two particles at rest in still gas, of densities 1000 and 8000 (species of injectors a, b).
TEST(ParticleSpecies, EachDensitySettlesAtItsOwnStokesLaw) {
    test::ScratchDirectory scratch("species-settling");
    const Scene scene = sceneOf(scratch, sprayDictionary(R"(
injectors
{
    a { model disc; centre (0 0 0); radius 0; count 1; mode allAtStart; density 1000; }
    b { model disc; centre (0 0.01 0); radius 0; count 1; mode allAtStart; density 8000; }
}
)"));
    ASSERT_EQ(scene.particles.species.size(), 2u);
    expectEachSettlesAtItsOwnStokesLaw(scene, {1000, 8000});
}

/// The scene with every particle of species s's density (one species), ids and starts unchanged.
Scene allOfSpecies(Scene scene, std::size_t s) {
    ParticleSettings& particles = scene.particles;
    particles.density = particles.species[s].density;
    particles.material = particles.species[s].material;
    particles.species.clear();
    particles.speciesOfInjector.clear();
    particles.injectorIds = {};
    return scene;
}

/// Each particle of a two-species scene, run until endTime, against the run where every particle
/// is of its species: the same bits of position, velocity and spin.
void expectEachAsItsSpeciesAlone(const Scene& scene) {
    const auto carrier = carrierOf(scene);
    Stepper mixed(scene, *carrier);
    while (!mixed.finished()) mixed.step();
    ASSERT_EQ(mixed.cloud().size(), 2u);
    for (std::size_t s = 0; s < 2; ++s) {
        const Scene single = allOfSpecies(scene, s);
        Stepper alone(single, *carrier);
        while (!alone.finished()) alone.step();
        ASSERT_EQ(alone.cloud().size(), 2u);
        const auto i = static_cast<std::size_t>(mixed.cloud().id[0] == s ? 0 : 1);
        const auto k = static_cast<std::size_t>(alone.cloud().id[0] == s ? 0 : 1);
        EXPECT_TRUE(mixed.cloud().position[i] == alone.cloud().position[k]) << "species " << s;
        EXPECT_TRUE(mixed.cloud().velocity[i] == alone.cloud().velocity[k]) << "species " << s;
        if (scene.physics.spin) {
            EXPECT_TRUE(mixed.cloud().angularVelocity[i] == alone.cloud().angularVelocity[k])
                << "species " << s;
        }
    }
    // The two really move differently: ρp 8000 lags the gas eight times longer than ρp 1000.
    const Vec3 slip = mixed.cloud().velocity[0] - mixed.cloud().velocity[1];
    EXPECT_GT(slip.norm(), 1e-3 * mixed.cloud().velocity[0].norm());
}

/// Eq. 3.3/3.4 and 3.18 with their ρp per particle: the Maxey–Riley step (history, added mass,
/// pressure gradient, lift, spin and its history, Faxén) takes each particle's own density, and
/// a particle of either species follows, bit for bit, its path in a run of its density alone
/// (the same ids, starts and steps; no term draws random numbers).
TEST(ParticleSpecies, UnsteadyForcesTakeEachParticlesOwnDensity) {
    test::ScratchDirectory scratch("species-unsteady");
    const std::string pair = R"(
injectors
{
    a { model disc; centre (0 0.0004 0); axis (1 0 0); radius 0; count 1; mode allAtStart;
        crossSpanSpeed 0; density 1000; radiusDistribution { type fixed; value 20e-6; } }
    b { model disc; centre (0 -0.0003 0); axis (1 0 0); radius 0; count 1; mode allAtStart;
        crossSpanSpeed 0; density 8000; radiusDistribution { type fixed; value 20e-6; } }
}
)";
    Scene jet = sceneOf(scratch, sprayDictionary(pair));
    ASSERT_EQ(jet.particles.species.size(), 2u);
    jet.collisions.model = CollisionModel::none;
    jet.surfaces.clear();
    jet.domain = {Vec3::Constant(-1), Vec3::Constant(1)};
    jet.time.dt = 2e-6;
    jet.time.endTime = 1e-3;
    jet.time.stopWhenAllDone = false;
    PhysicsSettings& physics = jet.physics;
    physics.history = HistoryModel::basset;
    physics.addedMass = physics.pressureGradient = true;
    physics.lift = LiftModel::saffmanMeiMagnus;
    physics.spin = physics.spinHistory = true;
    expectEachAsItsSpeciesAlone(jet);

    // Kim's finite-Reynolds kernel (its G1 takes ρp/ρf) and the Faxén terms, in a channel.
    Scene channel = jet;
    channel.carrier.type = CarrierType::planePoiseuille;
    channel.carrier.centrelineVelocity = 2;
    channel.carrier.channelHalfWidth = 1e-3;
    channel.physics.history = HistoryModel::kim;
    channel.physics.lift = LiftModel::none;
    channel.physics.spin = channel.physics.spinHistory = false;
    channel.physics.faxen = true;
    expectEachAsItsSpeciesAlone(channel);
}

/// One particle each of injectors a (id 0) and b (id 1), side by side in the default case's jet
/// (at the nozzle, where the gas is fastest), with what a and b give of their species and
/// `rest` appended to the dictionary; dt 1e-5, no collisions, no surfaces.
Scene particlePair(const test::ScratchDirectory& scratch, const std::string& a,
                   const std::string& b, const std::string& rest = "") {
    Scene scene = sceneOf(scratch, sprayDictionary(R"(
injectors
{
    a { model disc; centre (0 0.0005 0); radius 0; count 1; mode allAtStart; )" +
                                                   a + R"( }
    b { model disc; centre (0 -0.0005 0); radius 0; count 1; mode allAtStart; )" +
                                                   b + R"( }
}
collisions { model none; }
)") + rest); // after the case's own blocks, so that rest's keys replace theirs
    scene.surfaces.clear();
    scene.domain = {Vec3::Constant(-1e6), Vec3::Constant(1e6)};
    scene.time.dt = 1e-5;
    scene.time.stopWhenAllDone = false;
    return scene;
}

/// The stepper of scene after `steps` steps in carrier.
std::unique_ptr<Stepper> runFor(const Scene& scene, const CarrierField& carrier, int steps) {
    auto stepper = std::make_unique<Stepper>(scene, carrier);
    for (int n = 0; n < steps; ++n) stepper->step();
    return stepper;
}

/// Strong check of a model taking each particle's species: with a's values on particle 0 and
/// b's on particle 1, each particle moves (and heats) bit for bit as in a run whose particles
/// are all of its species, from the same place with the same id (so the same random draws).
void expectEachAsInARunOfItsSpeciesAlone(const std::string& a, const std::string& b,
                                         const std::string& rest, int steps) {
    test::ScratchDirectory scratch("species-alone");
    const Scene mixed = particlePair(scratch, a, b, rest);
    ASSERT_EQ(mixed.particles.species.size(), 2u);
    const Scene onlyA = particlePair(scratch, a, a, rest),
                onlyB = particlePair(scratch, b, b, rest);
    ASSERT_TRUE(onlyA.particles.alike() && onlyB.particles.alike());
    const auto carrier = carrierOf(mixed);
    const auto both = runFor(mixed, *carrier, steps);
    const auto aloneA = runFor(onlyA, *carrier, steps), aloneB = runFor(onlyB, *carrier, steps);
    const ParticleCloud& cloud = both->cloud();
    ASSERT_EQ(cloud.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        const ParticleCloud& alone = (cloud.id[i] == 0 ? aloneA : aloneB)->cloud();
        const std::size_t j = alone.id[0] == cloud.id[i] ? 0 : 1;
        ASSERT_EQ(alone.id[j], cloud.id[i]);
        EXPECT_TRUE(cloud.position[i] == alone.position[j]) << "particle " << cloud.id[i];
        EXPECT_TRUE(cloud.velocity[i] == alone.velocity[j]) << "particle " << cloud.id[i];
        if (!cloud.temperature.empty()) {
            EXPECT_EQ(cloud.temperature[i], alone.temperature[j]) << "particle " << cloud.id[i];
        }
    }
    // The species really differ: the mixed run's two particles do not move (or heat) alike.
    if (cloud.temperature.empty()) {
        EXPECT_GT((cloud.velocity[0] - cloud.velocity[1]).norm(), 1e-3 * cloud.velocity[0].norm());
    } else {
        EXPECT_GT(std::abs(cloud.temperature[0] - cloud.temperature[1]), 1e-3);
    }
}

/// Species a (index 0, particle id 0) and b (index 1, id 1) in code.
void twoSpecies(ParticleSettings& particles, const ParticleSpecies& a, const ParticleSpecies& b) {
    particles.density = a.density;
    particles.material = a.material;
    particles.specificHeat = a.specificHeat;
    particles.species = {a, b};
    particles.speciesOfInjector = {0, 1};
    particles.injectorIds = {{0, 1}, 2};
}

/// A scene without gas: two particles of the given species, the collision model given.
Scene twoBodyScene(const ParticleSpecies& a, const ParticleSpecies& b, CollisionModel model,
                   double dt) {
    Scene scene = test::singleParticleScene();
    scene.carrier.type = CarrierType::none;
    scene.fluid = {0, 0, 293.15};
    scene.particles.count = 2;
    scene.particles.radius.value = 1e-3;
    twoSpecies(scene.particles, a, b);
    scene.collisions.model = model;
    scene.collisions.restitution = {RestitutionModel::constant, 1.0, 3};
    scene.collisions.friction = {0, 0};
    scene.time.dt = dt;
    return scene;
}

/// The particles of cloud, already injected, as the stepper's.
void start(Stepper& stepper, ParticleCloud cloud) {
    RunCounters counters;
    counters.injected = static_cast<long>(cloud.size());
    cloud.angularVelocity.resize(cloud.size(), Vec3::Zero());
    stepper.resume(counters, std::move(cloud), {});
}

/// E [Pa] and ν as the bulk and shear moduli of a material.
MaterialSettings elastic(double youngs, double poisson) {
    return {youngs / (3 * (1 - 2 * poisson)), youngs / (2 * (1 + poisson))};
}

TEST(ParticleSpecies, HeadOnImpulseImpactOfTwoDensitiesConservesMomentumAndEnergy) {
    const ParticleSpecies light{1000, elastic(1e9, 0.3), 0}, heavy{8000, elastic(2e11, 0.28), 0};
    const Scene scene = twoBodyScene(light, heavy, CollisionModel::impulse, 1e-4);
    NoGas vacuum;
    Stepper stepper(scene, vacuum);
    const double radius = 1e-3;
    ParticleCloud cloud;
    cloud.add(0, Vec3(-radius - 5e-5, 0, 0), Vec3(2, 0, 0), radius);
    cloud.add(1, Vec3(radius + 5e-5, 0, 0), Vec3(-0.5, 0, 0), radius);
    start(stepper, cloud);
    stepper.step();
    ASSERT_EQ(stepper.collisions(), 1);
    const double ma = sphereMass(radius, 1000), mb = sphereMass(radius, 8000);
    const ParticleCloud& after = stepper.cloud();
    const double va = after.velocity[0].x(), vb = after.velocity[1].x();
    // Momentum and, with e = 1, kinetic energy; each velocity the elastic closed form
    // v_a' = ((m_a − m_b) v_a + 2 m_b v_b)/(m_a + m_b) (and a ↔ b).
    const double momentum = ma * 2 + mb * -0.5;
    const double energy = 0.5 * ma * 4 + 0.5 * mb * 0.25;
    EXPECT_NEAR(ma * va + mb * vb, momentum, 1e-15 * (ma * 2 + mb * 0.5));
    EXPECT_NEAR(0.5 * ma * va * va + 0.5 * mb * vb * vb, energy, 1e-14 * energy);
    EXPECT_NEAR(va, ((ma - mb) * 2 + 2 * mb * -0.5) / (ma + mb), 1e-14);
    EXPECT_NEAR(vb, ((mb - ma) * -0.5 + 2 * ma * 2) / (ma + mb), 1e-14);
}

TEST(ParticleSpecies, HertzContactOfTwoMaterialsLastsAsHertzTheoryWithTheCombinedModuli) {
    // Sphere a: ρ 2500, E 1e7 Pa, ν 0.3; sphere b: ρ 7800, E 4e7 Pa, ν 0.25; R = 1 mm, closing
    // at v = 1 m/s. Hertz (Eq. 2.59): 1/E* = (1 − ν_a²)/E_a + (1 − ν_b²)/E_b,
    // m* = m_a m_b/(m_a + m_b), R* = R/2; δ_max = (15 m* v²/(16 E* √R*))^(2/5),
    // t_c = 2.9432 δ_max / v (2 ∫₀¹ dx/√(1 − x^(5/2)) = 2.94324).
    const double radius = 1e-3, dt = 1e-6;
    const ParticleSpecies a{2500, elastic(1e7, 0.3), 0}, b{7800, elastic(4e7, 0.25), 0};
    const Scene scene = twoBodyScene(a, b, CollisionModel::softSphere, dt);
    NoGas vacuum;
    Stepper stepper(scene, vacuum);
    ParticleCloud cloud;
    cloud.add(0, Vec3(-radius - 5e-5, 0, 0), Vec3(0.5, 0, 0), radius);
    cloud.add(1, Vec3(radius + 5e-5, 0, 0), Vec3(-0.5, 0, 0), radius);
    start(stepper, cloud);
    const double ma = sphereMass(radius, 2500), mb = sphereMass(radius, 7800);
    long loaded = 0;
    for (int n = 0; n < 100000; ++n) {
        stepper.step();
        const ParticleCloud& c = stepper.cloud();
        const bool hasLoad = c.contactForce[0].squaredNorm() > 0;
        if (hasLoad) ++loaded;
        if (loaded > 0 && !hasLoad && (c.position[1] - c.position[0]).norm() > 2 * radius) break;
    }
    const double youngs = 1 / ((1 - 0.3 * 0.3) / 1e7 + (1 - 0.25 * 0.25) / 4e7);
    const double reduced = ma * mb / (ma + mb);
    const double closing = 1.0;
    const double depth =
        std::pow(15 * reduced * closing * closing / (16 * youngs * std::sqrt(radius / 2)), 0.4);
    const double hertz = 2.94324 * depth / closing;
    const ParticleCloud& c = stepper.cloud();
    EXPECT_NEAR(static_cast<double>(loaded) * dt, hertz, 2 * dt); // counted in whole steps
    // Elastic: the relative speed restored to O((dt/t_c)²), momentum to round-off.
    EXPECT_NEAR((c.velocity[1] - c.velocity[0]).x(), closing, 1e-4);
    EXPECT_NEAR(ma * c.velocity[0].x() + mb * c.velocity[1].x(), ma * 0.5 - mb * 0.5,
                1e-15 * (ma + mb));
    // The same contact with a's material on both sides is another: E* matters.
    const ContactPair same = contactPair({ma, radius, &a.material}, {mb, radius, &a.material});
    const ContactPair mixed = contactPair({ma, radius, &a.material}, {mb, radius, &b.material});
    EXPECT_NEAR(mixed.youngsModulus, youngs, 1e-9 * youngs);
    EXPECT_GT(same.youngsModulus, 0);
    EXPECT_LT(same.youngsModulus, 0.9 * youngs);
}

/// Scene run 600 steps in one go, and run 300 steps, checkpointed to scratch, read back and
/// resumed for the other 300 in a stepper of its own.
std::pair<std::unique_ptr<Stepper>, std::unique_ptr<Stepper>>
wholeAndResumedRuns(const test::ScratchDirectory& scratch, const Scene& scene,
                    const CarrierField& carrier) {
    auto whole = std::make_unique<Stepper>(scene, carrier);
    auto resumed = std::make_unique<Stepper>(scene, carrier);
    Stepper half(scene, carrier);
    for (int step = 0; step < 600; ++step) whole->step();
    for (int step = 0; step < 300; ++step) half.step();
    const RunFingerprint fingerprint =
        fingerprintOf(scratch.path / "constant" / "slidesProperties", scene.time.dt);
    writeCheckpoint(scratch.path, half.snapshot(), nullptr, {}, 0, {}, fingerprint);
    CheckpointState state = readCheckpoint(scratch.path, fingerprint);
    resumed->resume(state.counters, std::move(state.cloud), std::move(state.arrivals));
    for (int step = 0; step < 300; ++step) resumed->step();
    return {std::move(whole), std::move(resumed)};
}

TEST(ParticleSpecies, CheckpointOfTwoSpeciesRestartsToTheSameBits) {
    test::ScratchDirectory scratch("species-checkpoint");
    Scene scene = sceneOf(scratch, twoGuns("density 2500; material { bulkModulus 40e9; }",
                                           "density 8000;", "impulse"));
    ASSERT_EQ(scene.particles.species.size(), 2u);
    const auto carrier = carrierOf(scene);
    const auto [whole, resumed] = wholeAndResumedRuns(scratch, scene, *carrier);
    EXPECT_GT(whole->collisions(), 0);
    EXPECT_EQ(resumed->collisions(), whole->collisions());
    ASSERT_GT(whole->arrivals().size() + whole->cloud().size(), 500u);
    expectSameBits(*whole, *resumed);
}

TEST(ParticleSpecies, SimdRelaxationWithOwnDensitiesMatchesTheScalarLaneByLane) {
    // 37 particles (whole vectors and a padded tail at any width), densities 500 … 20000 mixed,
    // each with its own body acceleration (1 − ρf/ρp) g; the scalar relaxExactly with
    // dragResponseTime of the particle's own density is the reference.
    const DragParameters drag{DragModel::haiderLevenspiel, 1.2, 1.5e-5, 2500};
    const Vec3 g(0, -9.81, 0);
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> unit(0, 1);
    const std::size_t n = 37;
    std::vector<Vec3> x(n), v(n), u(n), w(n), a(n);
    std::vector<double> radius(n), h(n), density(n);
    for (std::size_t i = 0; i < n; ++i) {
        x[i] = Vec3(unit(random), unit(random), unit(random));
        v[i] = 10 * Vec3(unit(random), unit(random), unit(random));
        u[i] = 20 * Vec3(unit(random), unit(random), unit(random));
        w[i] = v[i];
        radius[i] = 5e-6 + 1e-4 * unit(random);
        h[i] = 1e-4 * (0.5 + unit(random));
        density[i] = i % 3 == 0 ? 500 : i % 3 == 1 ? 20000 : 3000 + 1000 * unit(random);
        a[i] = (1 - drag.fluidDensity / density[i]) * g;
    }
    std::vector<Vec3> xs = x, vs = v;
    relaxBatchExactly({xs, vs, xs, vs, u, w, radius, h, density, a}, drag, g, 1.0);
    for (std::size_t i = 0; i < n; ++i) {
        DragParameters own = drag;
        own.particleDensity = density[i];
        Vec3 xr = x[i], vr = v[i];
        relaxExactly(xr, vr, u[i], dragResponseTime(own, radius[i], (u[i] - w[i]).norm()), a[i],
                     h[i]);
        EXPECT_LE((xs[i] - xr).norm(), 1e-13 * xr.norm()) << i;
        EXPECT_LE((vs[i] - vr).norm(), 1e-13 * vr.norm()) << i;
    }
    // Without densities, the batch is the common-density one: bit for bit unchanged.
    std::vector<Vec3> xc = x, vc = v, xd = x, vd = v;
    relaxBatchExactly({xc, vc, xc, vc, u, w, radius, h}, drag, g, 1.0);
    const std::vector<double> common(n, drag.particleDensity);
    const std::vector<Vec3> commonA(n, g);
    relaxBatchExactly({xd, vd, xd, vd, u, w, radius, h, common, commonA}, drag, g, 1.0);
    for (std::size_t i = 0; i < n; ++i) {
        EXPECT_LE((xc[i] - xd[i]).norm(), 1e-13 * xc[i].norm()) << i;
        EXPECT_LE((vc[i] - vd[i]).norm(), 1e-13 * vc[i].norm()) << i;
    }
}

TEST(ParticleSpecies, FramesCarryEachParticlesDensityWhenTheyDiffer) {
    test::ScratchDirectory scratch("species-frames");
    std::ofstream(scratch.path / "constant" / "slidesProperties")
        << twoGuns("density 2500;", "density 8000;");
    const auto output = scratch.path / "out";
    ASSERT_EQ(
        test::runCli(scratch.path.string() + " --quiet --end-time 2e-3 --output " + output.string(),
                     scratch.path / "log"),
        0)
        << test::slurp(scratch.path / "log");
    const std::string vtp = test::slurp(output / "particles_000002.vtp");
    EXPECT_NE(vtp.find("Name=\"density\""), std::string::npos);
    const auto summary = nlohmann::json::parse(test::slurp(output / "summary.json"));
    EXPECT_EQ(summary["settings"]["particles"]["species"].size(), 2u);
}

TEST(ParticleSpecies, AdaptiveRungeKuttaMovesEachDensityAsItsOwnRun) {
    // dv/dt = (u − v)/τ(ρp) + (1 − ρf/ρp) g in Dormand–Prince sub-steps (Eq. 4.18–4.29):
    // particle i's sub-steps depend on its own state alone, so with its own ρp and a in the
    // stages and the error control the same arithmetic as a run of its density alone: the same
    // bits.
    expectEachAsInARunOfItsSpeciesAlone("density 1000;", "density 8000;",
                                        "time { integrator adaptiveRungeKutta; }", 200);
}

TEST(ParticleSpecies, EddyInteractionDispersesEachDensityAsItsOwnRun) {
    // Eddy interaction (Gosman & Ioannides): the eddy–particle interaction time takes the
    // particle's τ(ρp) and drift τ a (the crossing length), in the SIMD lanes and in the scalar
    // step of a new eddy. Random draws are keyed by (seed, id): the runs of one species keep
    // the two-injector layout, so ids and draws are the same, and each particle's eddies must
    // be too.
    expectEachAsInARunOfItsSpeciesAlone("density 1000;", "density 8000;",
                                        "carrier { turbulence { scaling jetLocal; intensity "
                                        "0.25; lengthScaleToHalfWidth 0.2; } } "
                                        "physics { dispersion { model eddyInteraction; } }",
                                        300);
}

TEST(ParticleSpecies, HeatTransferHeatsEachSpeciesAsItsOwnRun) {
    // τ_θ = ρp c_p R²/(3 K_f Nu/2) (Eq. 3.25–3.27) of each particle's own ρp and c_p, under the
    // Ranz–Marshall correlation and the history memory of Michaelides & Feng (Eq. 3.29).
    const std::string a = "density 8960; specificHeat 385;", b = "density 2500; specificHeat 840;";
    for (const std::string model : {"ranzMarshall", "michaelidesFeng"}) {
        SCOPED_TRACE(model);
        expectEachAsInARunOfItsSpeciesAlone(
            a, b,
            "particles { specificHeat 385; injectionTemperature 500; } physics { heatTransfer "
            "{ "
            "model " +
                model + "; } }",
            200);
    }
    // Differing specific heats alone, at one density.
    expectEachAsInARunOfItsSpeciesAlone(
        "specificHeat 385;", "specificHeat 840; density 5680;",
        "particles { specificHeat 385; injectionTemperature 500; } physics { heatTransfer { "
        "model ranzMarshall; } }",
        200);
}

TEST(ParticleSpecies, EachSpeciesHeatsAtItsOwnLumpedExponential) {
    // Two particles at the nozzle moving with uniform 300 K gas (no slip: Re = 0, Nu = 2),
    // injected at 500 K: θ(t) = θf + (θ0 − θf) e^(−t/τ_θ), τ_θ = ρp c_p R²/(3 K_f), of copper
    // (ρp 8960, c_p 385) and glass (ρp 2500, c_p 840): ρp c_p differ by 1.64. Exact for the
    // frozen gas: 1e-12 of the 200 K span, the round-off of the time sum and exp.
    Scene scene = test::singleParticleScene();
    scene.particles.count = 2;
    scene.particles.radius.value = 40e-6;
    twoSpecies(scene.particles, {8960, {}, 385}, {2500, {}, 840});
    scene.particles.injectionTemperature = 500;
    scene.fluid.thermalConductivity = 0.0257;
    scene.fluid.specificHeat = 1005;
    scene.physics.heatTransfer = HeatTransferModel::ranzMarshall;
    const auto tauOf = [&](const ParticleSpecies& species) {
        return thermalResponseTime(species.density, species.specificHeat, 40e-6, 2.0, 0.0257);
    };
    const double fastest = tauOf(scene.particles.species[1]);
    scene.time.dt = 0.1 * fastest;
    scene.time.endTime = 20 * fastest;
    const test::UniformTurbulentGas gas(0.0, 0.0, 300, Vec3(3, 0, 0));
    Stepper stepper(scene, gas);
    double apart = 0; // the largest difference of the two temperatures
    while (!stepper.finished()) {
        stepper.step();
        const ParticleCloud& cloud = stepper.cloud();
        ASSERT_EQ(cloud.size(), 2u);
        apart = std::max(apart, std::abs(cloud.temperature[0] - cloud.temperature[1]));
        for (std::size_t i = 0; i < 2; ++i) {
            const double tau = tauOf(scene.particles.species[cloud.id[i]]);
            ASSERT_NEAR(cloud.temperature[i], 300 + 200 * std::exp(-stepper.time() / tau),
                        200 * 1e-12)
                << "particle " << cloud.id[i] << ", t = " << stepper.time() / tau << " τ_θ";
        }
    }
    EXPECT_GT(apart, 20.0); // 32 K near t = 2 τ_θ of glass
}

TEST(ParticleSpecies, ChargedSpeciesMoveAsTheirOwnRuns) {
    // Lorentz force of Eq. 2.93 with q/m of each particle's own mass 4/3 π R³ ρp, and its own
    // drag and buoyancy: under the exact Lorentz–drag flow and under adaptiveRungeKutta. q
    // 2e-11 C in E 2e4 V/m: qE/m 190 m/s² on the light particle (ρp 1000), 24 on the heavy one,
    // against a drag of about U/τ = 500 and 60 m/s².
    const std::string fields = "physics { electromagnetic { model lorentz; E (0 2e4 0); B (0 0 5); "
                               "charge { model fixed; value 2e-11; } } } ";
    for (const std::string time : {"", "time { integrator adaptiveRungeKutta; }"}) {
        SCOPED_TRACE(time);
        expectEachAsInARunOfItsSpeciesAlone("density 1000;", "density 8000;", fields + time, 200);
    }
}

TEST(ParticleSpecies, MagnetisableSpeciesMoveAsTheirOwnRuns) {
    // Eq. 2.110 with each particle's own χm (injectors.NAME.susceptibility): a coil of radius
    // 2 mm around the jet 1 cm downstream (0.94 T at its centre) draws the χm = 0.5 particle
    // with up to χm B²/(µ0 µr ρp a) ≈ 2e4 m/s², the χm = 0.01 one fifty times less.
    const std::string fields =
        "physics { electromagnetic { model lorentz; coils { ring { centre (0.01 0 0); axis (1 0 "
        "0); radius 2e-3; current 3000; } } magnetisation { model linear; } } } ";
    expectEachAsInARunOfItsSpeciesAlone("susceptibility 0.5;", "susceptibility 0.01;", fields, 200);
}

TEST(ParticleSpecies, CoulombKicksOfTwoDensitiesConserveMomentum) {
    // Two charges 1 mm apart at rest without gas, densities 1000 and 8000: the pair's forces
    // are equal and opposite (Eq. 2.94 × 2.97), so each kick v += F h/(2m) with the particle's
    // own mass keeps m_a v_a + m_b v_b = 0, and v_a = −(m_b/m_a) v_b = −8 v_b, to round-off. A
    // kick by one common mass would break both by the factor 8.
    const double radius = 1e-4, charge = 1e-11;
    Scene scene = twoBodyScene({1000, {}, 0}, {8000, {}, 0}, CollisionModel::none, 1e-4);
    scene.particles.radius.value = radius;
    ElectromagneticSettings& fields = scene.physics.electromagnetic;
    fields.model = ElectromagneticModel::lorentz;
    fields.chargeValue = charge;
    fields.coulomb = {CoulombModel::shifted, 5e-3, 1};
    scene.time.endTime = 100 * scene.time.dt;
    scene.domain = {Vec3::Constant(-0.1), Vec3::Constant(0.1)}; // the cut-off's cell grid
    NoGas vacuum;
    Stepper stepper(scene, vacuum);
    ParticleCloud cloud;
    cloud.add(0, Vec3(-5e-4, 0, 0), Vec3::Zero(), radius);
    cloud.add(1, Vec3(5e-4, 0, 0), Vec3::Zero(), radius);
    cloud.charge.assign(2, charge);
    start(stepper, cloud);
    while (!stepper.finished()) stepper.step();
    const ParticleCloud& after = stepper.cloud();
    const double ma = sphereMass(radius, 1000), mb = sphereMass(radius, 8000);
    const double va = after.velocity[0].x(), vb = after.velocity[1].x();
    ASSERT_LT(va, -1e-3); // pushed apart
    EXPECT_NEAR(ma * va + mb * vb, 0, 1e-14 * ma * std::abs(va));
    EXPECT_NEAR(va / vb, -8, 8e-14);
}

TEST(ParticleSpecies, EachDensityGyratesOnItsOwnLarmorCircle) {
    // Without gas, dv/dt = v × Ω, Ω = qB/m, m = 4/3 π R³ ρp: each particle circles the centre
    // c = x0 − Ω × v0/ω² at the Larmor radius |v⊥|/ω with the period 2π/ω, its velocity turned
    // by −ωt about B. Densities 1000 and 8000 (ω differs 8-fold); q 1e-6 C, B 1 T, R 1 mm,
    // |v| 1 m/s; 100 periods of the light one at 37 steps a period, 12.5 of the heavy one. The
    // flow is exact: 1e-8 of the radius over that time, as the one-species Larmor test.
    const double radius = 1e-3, charge = 1e-6, magnetic = 1.0;
    Scene scene = twoBodyScene({1000, {}, 0}, {8000, {}, 0}, CollisionModel::none, 1.0);
    scene.particles.radius.value = radius;
    ElectromagneticSettings& fields = scene.physics.electromagnetic;
    fields.model = ElectromagneticModel::lorentz;
    fields.magneticField = Vec3(0, 0, magnetic);
    fields.chargeValue = charge;
    const auto gyrationOf = [&](std::uint64_t id) {
        return Vec3(0, 0, charge * magnetic / sphereMass(radius, id == 0 ? 1000 : 8000));
    };
    const double lightPeriod = 2 * std::numbers::pi / gyrationOf(0).norm();
    scene.time.dt = lightPeriod / 37;
    scene.time.endTime = 200 * lightPeriod;
    NoGas vacuum;
    Stepper stepper(scene, vacuum);
    ParticleCloud cloud;
    const Vec3 origin[2] = {Vec3(0, 0, 0), Vec3(100, 0, 0)}, v0(0, 1, 0);
    cloud.add(0, origin[0], v0, radius);
    cloud.add(1, origin[1], v0, radius);
    cloud.charge.assign(2, charge);
    start(stepper, cloud);
    for (int n = 0; n < 3700; ++n) stepper.step();
    const ParticleCloud& after = stepper.cloud();
    for (std::size_t i = 0; i < 2; ++i) {
        const Vec3 omega = gyrationOf(after.id[i]);
        const double w = omega.norm(), t = stepper.time();
        const Vec3 centre = origin[after.id[i]] - omega.cross(v0) / (w * w);
        const Vec3 velocity = Eigen::AngleAxisd(-w * t, Vec3::UnitZ()) * v0;
        const double larmor = v0.norm() / w;
        EXPECT_LE((after.velocity[i] - velocity).norm(), 1e-8 * v0.norm()) << after.id[i];
        EXPECT_LE((after.position[i] - centre - omega.cross(velocity) / (w * w)).norm(),
                  1e-8 * larmor)
            << after.id[i];
        EXPECT_NEAR((after.position[i] - centre).norm(), larmor, 1e-8 * larmor) << after.id[i];
    }
}

TEST(ParticleSpecies, EveryModelTakesDifferingSpecies) {
    test::ScratchDirectory scratch("species-models");
    const auto outcome = [&](const std::string& physics, const std::string& b = "density 8000;") {
        try {
            sceneOf(scratch, twoGuns("", b) + physics);
        } catch (const InputError& error) {
            return error.key() + ": " + error.reason();
        }
        return std::string("accepted");
    };
    EXPECT_EQ(outcome("physics { history { model basset; } addedMass on; pressureGradient on; "
                      "lift saffmanMei; spin on; }"),
              "accepted");
    EXPECT_EQ(outcome("carrier { turbulence { scaling jetLocal; intensity 0.25; "
                      "lengthScaleToHalfWidth 0.2; } } physics { dispersion { model "
                      "eddyInteraction; } }"),
              "accepted");
    for (const std::string b : {"density 8000;", "specificHeat 900;"})
        EXPECT_EQ(outcome("particles { specificHeat 460; } physics { heatTransfer { model "
                          "ranzMarshall; } }",
                          b),
                  "accepted");
    EXPECT_EQ(outcome("physics { electromagnetic { model lorentz; E (0 1 0); } }"), "accepted");
    EXPECT_EQ(outcome("time { integrator adaptiveRungeKutta; }"), "accepted");
    // Differing materials alone take every model that reads no material.
    EXPECT_EQ(outcome("physics { history { model basset; } }", "material { yieldStress 1e8; }"),
              "accepted");
    // Terms left to auto that take each particle's density are the analysis's to decide.
    test::ScratchDirectory other("species-auto");
    const Scene scene = sceneOf(other, twoGuns("", "density 8000;"));
    for (const AutomaticTerm& term : scene.physics.automaticTerms) {
        if (term.term == PhysicsTerm::history || term.term == PhysicsTerm::addedMass ||
            term.term == PhysicsTerm::heatTransfer) {
            EXPECT_EQ(term.unavailable.find("differing"), std::string::npos) << term.unavailable;
        }
    }
}

// ---- a file's densities: a CSV's rho column, a previous run's density
// ------------------------

/// constant/rows.csv of scratch holding csv, and the file injector `rows` reading it (with the
/// extra keys given).
std::string rowsInjector(const test::ScratchDirectory& scratch, const std::string& csv,
                         const std::string& extra = "") {
    std::ofstream(scratch.path / "constant" / "rows.csv") << csv;
    return "injectors { rows { model file; file \"constant/rows.csv\"; " + extra + " } }\n";
}

/// 300 rows of 40 µm radius in two streams at 20 m/s that cross 1 cm after the nozzle, a pair
/// of rows (one of each stream) every 10 µs, each pair at its own z: most pairs meet. With
/// densities, a rho column, row k of densities[k % size].
std::string crossingStreams(const std::vector<double>& densities) {
    std::string csv = densities.empty() ? "x y z u v w r t\n" : "x y z u v w r t rho\n";
    char row[160];
    for (int k = 0; k < 300; ++k) {
        const bool upper = k % 2 == 0;
        const int length =
            std::snprintf(row, sizeof row, "0 %g %g 20 %g 0 4e-5 %.17g", upper ? 1e-3 : -1e-3,
                          ((k / 2) % 7 - 3) * 1e-5, upper ? -2.0 : 2.0, (k / 2) * 1e-5);
        if (!densities.empty())
            std::snprintf(row + length, sizeof row - std::size_t(length), " %.17g",
                          densities[std::size_t(k) % densities.size()]);
        (csv += row) += '\n';
    }
    return csv;
}

/// The crossing streams with impulse collisions, to endTime 6 ms.
Scene crossingScene(const test::ScratchDirectory& scratch, const std::vector<double>& densities) {
    Scene scene =
        sceneOf(scratch, sprayDictionary(rowsInjector(scratch, crossingStreams(densities)) +
                                         "collisions { model impulse; }\n"));
    scene.time.endTime = 6e-3;
    return scene;
}

TEST(ParticleSpecies, EachRowsDensitySettlesAtItsOwnStokesLaw) {
    // Rows of densities 1000, 8000 and 1000 in one CSV: two species, each id its row's.
    test::ScratchDirectory scratch("species-rows-settling");
    const Scene scene = sceneOf(scratch, sprayDictionary(rowsInjector(scratch, R"(x y z u v w r rho
0 0 0 0 0 0 80e-6 1000
0 0.01 0 0 0 0 80e-6 8000
0 0.02 0 0 0 0 80e-6 1000
)")));
    ASSERT_EQ(scene.particles.species.size(), 2u);
    EXPECT_EQ(scene.particles.species[0].density, 1000);
    EXPECT_EQ(scene.particles.species[1].density, 8000);
    EXPECT_EQ(scene.particles.speciesOf(0), 0);
    EXPECT_EQ(scene.particles.speciesOf(1), 1);
    EXPECT_EQ(scene.particles.speciesOf(2), 0);
    // The injector's material with each row's density.
    EXPECT_TRUE(scene.particles.materialOf(1) == scene.particles.materialOf(0));
    expectEachSettlesAtItsOwnStokesLaw(scene, {1000, 8000, 1000});
}

TEST(ParticleSpecies, RhoColumnOfTheParticlesOwnDensityRunsBitForBitAsWithoutIt) {
    test::ScratchDirectory a("species-rows-plain"), b("species-rows-same");
    const Scene plain = crossingScene(a, {});
    const Scene given = crossingScene(b, {plain.particles.density});
    ASSERT_TRUE(given.particles.alike());
    const auto carrier = carrierOf(plain);
    Stepper first(plain, *carrier), second(given, *carrier);
    while (!first.finished()) first.step();
    while (!second.finished()) second.step();
    EXPECT_GT(first.collisions(), 10);
    EXPECT_EQ(first.collisions(), second.collisions());
    ASSERT_GT(first.arrivals().size(), 100u);
    expectSameBits(first, second);

    // Rows all of one other density: one species, theirs.
    test::ScratchDirectory c("species-rows-other");
    const Scene other = crossingScene(c, {3000});
    EXPECT_TRUE(other.particles.alike());
    EXPECT_EQ(other.particles.density, 3000);
}

TEST(ParticleSpecies, CheckpointOfRowsOfTwoDensitiesRestartsToTheSameBits) {
    test::ScratchDirectory scratch("species-rows-checkpoint");
    const Scene scene = crossingScene(scratch, {2500, 8000});
    ASSERT_EQ(scene.particles.species.size(), 2u);
    const auto carrier = carrierOf(scene);
    const auto [whole, resumed] = wholeAndResumedRuns(scratch, scene, *carrier);
    EXPECT_GT(whole->collisions(), 10);
    EXPECT_EQ(resumed->collisions(), whole->collisions());
    ASSERT_GT(whole->arrivals().size(), 100u);
    expectSameBits(*whole, *resumed);
}

TEST(ParticleSpecies, ArrivalsAndFramesCarryEachRowsDensity) {
    test::ScratchDirectory scratch("species-rows-output");
    std::ofstream(scratch.path / "constant" / "slidesProperties")
        << sprayDictionary(rowsInjector(scratch, crossingStreams({2500, 8000})) +
                           "output { hdf5 yes; carrierResolution (8 4 4); }\n");
    const auto output = scratch.path / "out";
    ASSERT_EQ(
        test::runCli(scratch.path.string() + " --quiet --end-time 6e-3 --output " + output.string(),
                     scratch.path / "log"),
        0)
        << test::slurp(scratch.path / "log");
    // Row k (particle id k) is of density 2500 (k even) or 8000 (k odd), exactly as written.
    const auto densityOf = [](std::uint64_t id) { return id % 2 == 0 ? 2500.0 : 8000.0; };
    const Hdf5File h5(output / "particles.h5", Hdf5Access::readOnly);
    const auto ids = h5.readUInt64("/arrivals/id");
    const auto densities = h5.readDoubles("/arrivals/density", 1);
    ASSERT_GT(ids.size(), 100u);
    ASSERT_EQ(densities.size(), ids.size());
    for (std::size_t k = 0; k < ids.size(); ++k) ASSERT_EQ(densities[k], densityOf(ids[k])) << k;
    const auto frameIds = h5.readUInt64("/frames/000002/id");
    const auto frameDensities = h5.readDoubles("/frames/000002/density", 1);
    ASSERT_GT(frameIds.size(), 100u);
    ASSERT_EQ(frameDensities.size(), frameIds.size());
    for (std::size_t k = 0; k < frameIds.size(); ++k)
        ASSERT_EQ(frameDensities[k], densityOf(frameIds[k])) << k;
    const auto summary = nlohmann::json::parse(test::slurp(output / "summary.json"));
    EXPECT_EQ(summary["settings"]["injectors"]["rows"]["species"], nlohmann::json({0, 1}));

    // A run chained from these arrivals takes their densities: its row k is the k-th arrival in
    // time (integrate/previous_run.h).
    test::ScratchDirectory next("species-rows-output-chained");
    const Scene chained =
        sceneOf(next, sprayDictionary("injectors { fromA { model file; file \"" +
                                      (output / "particles.h5").string() + "\"; } }\n"));
    const auto times = h5.readDoubles("/arrivals/time", 1);
    std::vector<std::size_t> order(ids.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return times[a] < times[b]; });
    ASSERT_EQ(chained.particles.count, long(ids.size()));
    ASSERT_EQ(chained.particles.species.size(), 2u);
    for (std::size_t k = 0; k < ids.size(); ++k)
        ASSERT_EQ(chained.particles.densityOf(k), densities[order[k]]) << k;
}

TEST(ParticleSpecies, ChainedRunTakesThePreviousRunsDensities) {
    // A particles.h5 by the run's own writer: three particles of densities 1000, 8000 and 2000,
    // the last arrived; the arrivals in the opposite order of time.
    test::ScratchDirectory scratch("species-rows-chained");
    const std::vector<std::uint64_t> ids{7, 8, 9};
    const std::vector<Vec3> positions{{0.01, 0.001, 0}, {0.02, -0.002, 0}, {0.06, 0, 0}};
    const std::vector<Vec3> velocities{{20, 0.5, 0}, {18, -1, 0}, {0, 0, 0}};
    const std::vector<double> radii{40e-6, 50e-6, 60e-6}, densities{1000, 8000, 2000};
    const std::vector<std::int32_t> states{0, 0, 1};
    {
        ParticlesHdf5 h5(scratch.path, "chained");
        ParticleFrame frame{ids, positions, velocities, radii, states};
        frame.density = densities;
        h5.writeFrame(0.0, frame);
        std::vector<Arrival> arrivals(3);
        for (std::size_t k = 0; k < 3; ++k)
            arrivals[k] = {ids[k],        0,       3e-3 - 1e-3 * double(k), positions[k],
                           velocities[k], radii[k]};
        h5.finish(arrivals, densities);
    }
    const auto file = scratch.path / ParticlesHdf5::fileName;
    const auto chained = [&](const std::string& coeffs) {
        return sceneOf(scratch, sprayDictionary("injectors { fromA { model file; file \"" +
                                                file.string() + "\"; " + coeffs + " } }\n"));
    };
    // Its arrivals, in order of arrival time: 2000, 8000, 1000.
    const Scene fromArrivals = chained("");
    ASSERT_EQ(fromArrivals.particles.count, 3);
    ASSERT_EQ(fromArrivals.particles.species.size(), 3u);
    EXPECT_EQ(fromArrivals.particles.densityOf(0), 2000);
    EXPECT_EQ(fromArrivals.particles.densityOf(1), 8000);
    EXPECT_EQ(fromArrivals.particles.densityOf(2), 1000);
    // Its frame's particles in flight: 1000, 8000.
    const Scene fromFrame = chained("fileCoeffs { source frame; time 0; }");
    ASSERT_EQ(fromFrame.particles.count, 2);
    ASSERT_EQ(fromFrame.particles.species.size(), 2u);
    EXPECT_EQ(fromFrame.particles.densityOf(0), 1000);
    EXPECT_EQ(fromFrame.particles.densityOf(1), 8000);
}

TEST(ParticleSpecies, BadRowDensitiesAndWhatTheyCannotGoWithAreRefused) {
    test::ScratchDirectory scratch("species-rows-refusals");
    const auto table = scratch.path / "constant" / "rows.csv";
    const auto refusal = [&](const std::string& csv, const std::string& dictionary) {
        try {
            sceneOf(scratch, sprayDictionary(rowsInjector(scratch, csv)) + dictionary);
        } catch (const InputError& error) {
            const std::string where = error.file() == table.string()
                                          ? "rows.csv:" + std::to_string(error.line()) + " "
                                          : "";
            return where + error.key() + ": " + error.reason();
        }
        return std::string("accepted");
    };
    const std::string header = "x y z u v w r rho\n";
    EXPECT_EQ(refusal(header + "0 0 0 1 1 1 1e-4 1000\n0 0 0 1 1 1 1e-4 -5\n", ""),
              "rows.csv:3 rho: must be a positive number (kg/m^3)");
    EXPECT_EQ(refusal(header + "0 0 0 1 1 1 1e-4 0\n", ""),
              "rows.csv:2 rho: must be a positive number (kg/m^3)");
    EXPECT_EQ(refusal(header + "0 0 0 1 1 1 1e-4 inf\n", ""),
              "rows.csv:2 rho: expected a finite number, found 'inf'");
    const std::string twoDensities = header + "0 0 0 1 1 1 1e-4 1000\n0 0 0 1 1 1 1e-4 8000\n";
    // Re-injected ids lie past all blocks, with no row: a file injector re-injects nothing.
    EXPECT_EQ(refusal(twoDensities, "injectors { rows { reinjectEscaped yes; } }\n"),
              "injectors.rows.reinjectEscaped: a file's or an ensemble's particles are its rows: "
              "none to draw anew");
    EXPECT_EQ(refusal(twoDensities, "injectors { rows { density 2500; } }\n"),
              "injectors.rows.density: its file gives its particles' densities "
              "(constant/rows.csv)");
    // Every model takes each particle's density, a row's as an injector's.
    EXPECT_EQ(refusal(twoDensities, "physics { addedMass on; pressureGradient on; }\n"),
              "accepted");
    EXPECT_EQ(refusal(twoDensities,
                      "time { integrator adaptiveRungeKutta; } collisions { model none; }\n"),
              "accepted");
}

} // namespace
} // namespace slides
