// ctest-labels: electromagnetic physics
// Coulomb forces between charged particles (Section 2.7.1: Eq. 2.94 truncated by the shift of
// Eq. 2.97, physics/coulomb.h; summed through the cell grid, collide/coulomb_forces.h):
//  - the pair: Coulomb's law k q_i q_j/r² at r ≪ r_c, force = −dU/dr, both zero at r_c, bounded
//    at and below the touching distance;
//  - a random cloud: the grid's force on every particle equals the O(N²) direct sum with the same
//    cut-off to 1e-12 of the sum of the pair forces' magnitudes (round-off), the pair energies
//    likewise, Newton's third law to round-off, the same bits at any thread count or cloud order;
//  - through the stepper (velocity Verlet): two opposite charges on a circular orbit about their
//    centre of mass keep the period of Kepler's third law with the Coulomb constant and their
//    radius, to the second order of the step; a small like-charged cloud that expands through
//    the cut-off keeps its energy (kinetic + pair potential) to the second order of the step;
//    a run of 300 particles is the same bit for bit at any thread count and across a restart;
//  - the scene analysis's default step: a tenth of the Coulomb time scale of a touching pair.
#include "../support/test_scenes.h"
#include "slides/analysis/scene_analysis.h"
#include "slides/carrier/no_gas.h"
#include "slides/collide/coulomb_forces.h"
#include "slides/physics/contact_pair.h"
#include "slides/physics/coulomb.h"
#include "slides/run/stepper.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <numeric>
#include <random>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace slides {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double radius = 50e-6; // [m], test::singleParticleScene's
constexpr double density = 2500; // [kg/m³]
const double mass = sphereMass(radius, density);

void setThreads(int threads) {
#ifdef _OPENMP
    omp_set_num_threads(threads);
#else
    (void)threads;
#endif
}

CoulombSettings shifted(double cutoff) { return {CoulombModel::shifted, cutoff, 1}; }

TEST(CoulombPair, IsCoulombsLawWellInsideTheCutoffAndVanishesAtIt) {
    const CoulombSettings settings = shifted(1e-2);
    const double k = settings.coulombConstant();
    EXPECT_NEAR(k, 8.9875517923e9, 1e-1); // 1/(4π ε0), CODATA 2018
    const double q1 = 2e-12, q2 = -3e-12;
    const CoulombPair pair = coulombPair(settings, q1, q2, radius, radius);
    // Point charges (no touching distance) at r = 1e-5 r_c: Coulomb's law, which the shift
    // changes by 2 (r/r_c)² = 2e-10.
    const CoulombPair points = {k * (q1 * q2), settings.cutoff, 0};
    const double r = 1e-7;
    EXPECT_NEAR(points.forceOn(Vec3(r, 0, 0)).x() / (k * q1 * q2 / (r * r)), 1.0, 3e-10);
    // Overlapping particles (r = 5e-7 m < R_i + R_j = 1e-4 m): the force at touch, along the
    // separation, opposite charges attracting.
    const double touch = 2 * radius, c2 = settings.cutoff * settings.cutoff;
    const double atTouch =
        k * q1 * q2 * (1 / (touch * touch) + 2 / c2 - 3 * touch * touch / (c2 * c2));
    const Vec3 force = pair.forceOn(Vec3(3e-7, -4e-7, 0));
    EXPECT_NEAR(force.norm(), std::abs(atTouch), 1e-12 * std::abs(atTouch));
    EXPECT_NEAR(force.normalized().dot(Vec3(-0.6, 0.8, 0)), 1.0, 1e-15);
    // F = −dU/dr (central difference, error ~ (δ/r)² U''' ≈ 1e-8 of F at δ = 1e-4 r).
    for (const double at : {1e-4, 2e-3, 9e-3}) {
        const double step = 1e-4 * at;
        const double slope = (points.energy(at + step) - points.energy(at - step)) / (2 * step);
        const double f = points.forceOn(Vec3(at, 0, 0)).x();
        EXPECT_NEAR(-slope / f, 1.0, 1e-6) << "r " << at;
    }
    // Eq. 2.97: potential and force zero at r_c (to the round-off of their terms).
    const double scale = std::abs(k * q1 * q2) / settings.cutoff;
    EXPECT_LT(std::abs(points.energy(settings.cutoff)), 1e-15 * scale);
    EXPECT_LT(points.forceOn(Vec3(settings.cutoff, 0, 0)).norm(), 1e-15 * scale / settings.cutoff);
    // Coincident centres: no force (not NaN); the energy stays finite.
    EXPECT_EQ(pair.forceOn(Vec3::Zero()), Vec3::Zero());
    EXPECT_TRUE(std::isfinite(pair.energy(0)));
    // Particles larger than the cut-off feel nothing inside it.
    const CoulombPair large = coulombPair(shifted(1e-4), q1, q2, 1e-4, 1e-4);
    EXPECT_EQ(large.forceOn(Vec3(5e-5, 0, 0)).norm(), 0.0);
}

/// count particles in a 5 mm cube, radii 10–40 µm, charges uniform in ±1 pC, ids shuffled (so
/// the direct sum's order is not the grid's), one pair coincident and one overlapping.
/// The box the random clouds below lie in.
const Box cloudBox{Vec3::Zero(), Vec3::Constant(5e-3)};

ParticleCloud randomChargedCloud(int count, unsigned seed) {
    std::mt19937_64 generator(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<ParticleId> ids(static_cast<std::size_t>(count));
    std::iota(ids.begin(), ids.end(), ParticleId{0});
    std::shuffle(ids.begin(), ids.end(), generator);
    ParticleCloud cloud;
    for (int n = 0; n < count; ++n) {
        const Vec3 x = 5e-3 * Vec3(unit(generator), unit(generator), unit(generator));
        cloud.add(ids[static_cast<std::size_t>(n)], x, Vec3::Zero(), 1e-5 + 3e-5 * unit(generator));
        cloud.charge.push_back(1e-12 * (2 * unit(generator) - 1));
    }
    cloud.position[1] = cloud.position[0];
    cloud.position[3] = cloud.position[2] + Vec3(1e-5, 0, 0);
    return cloud;
}

TEST(CoulombForces, EqualTheDirectSumOverAllPairsWithinTheCutoff) {
    const CoulombSettings settings = shifted(1e-3);
    const ParticleCloud cloud = randomChargedCloud(600, 11);
    CoulombForces grid(settings, density, cloudBox);
    grid.evaluate(cloud);
    const std::size_t count = cloud.size();
    long partners = 0;
    double directEnergy = 0, energyScale = 0;
    Vec3 total = Vec3::Zero();
    double totalScale = 0, largestDeviation = 0;
    for (std::size_t i = 0; i < count; ++i) {
        Vec3 direct = Vec3::Zero();
        double scale = 0; // Σ |F_ij|: the round-off of the sum is relative to it
        for (std::size_t j = 0; j < count; ++j) {
            const Vec3 separation = cloud.position[i] - cloud.position[j];
            if (j == i || separation.norm() >= settings.cutoff) continue;
            const CoulombPair pair = coulombPair(settings, cloud.charge[i], cloud.charge[j],
                                                 cloud.radius[i], cloud.radius[j]);
            const Vec3 force = pair.forceOn(separation);
            direct += force;
            scale += force.norm();
            ++partners;
            if (j > i) {
                directEnergy += pair.energy(separation.norm());
                energyScale += std::abs(pair.energy(separation.norm()));
            }
        }
        ASSERT_TRUE(grid.forces()[i].allFinite()) << "particle " << i;
        const double deviation = (grid.forces()[i] - direct).norm() / scale;
        EXPECT_LE(deviation, 1e-12) << "particle " << i;
        largestDeviation = std::max(largestDeviation, deviation);
        total += grid.forces()[i];
        totalScale += scale;
    }
    std::printf("Coulomb grid against the direct sum: %zu particles, %.1f partners each, largest "
                "deviation %.1e of Σ|F_ij|\n",
                count, static_cast<double>(partners) / static_cast<double>(count),
                largestDeviation);
    EXPECT_GT(partners, 10 * static_cast<long>(count)); // the test has pairs to get wrong
    EXPECT_LE(std::abs(grid.potentialEnergy() - directEnergy), 1e-12 * energyScale);
    EXPECT_LE(total.norm(), 1e-14 * totalScale); // equal and opposite pair forces
}

// A particle flung out of the domain in a step (a charge far too large for the step, say) is
// removed at the step's end: until then it neither feels nor exerts a force, however far it went
// or if its state is no longer finite, and the others' forces are those without it.
TEST(CoulombForces, LeaveOutTheParticlesOutsideTheDomain) {
    const CoulombSettings settings = shifted(1e-3);
    const ParticleCloud inside = randomChargedCloud(300, 13);
    ParticleCloud withStrays = inside;
    const Vec3 strays[] = {Vec3(1e300, 0, 0), Vec3(-1e20, 1e20, 3e-3), Vec3(std::nan(""), 0, 0),
                           cloudBox.max + Vec3(1e-9, 0, 0),
                           Vec3::Constant(std::numeric_limits<double>::infinity())};
    for (const Vec3& stray : strays) {
        withStrays.add(static_cast<ParticleId>(withStrays.size()), stray, Vec3::Zero(), 1e-5);
        withStrays.charge.push_back(1e-3);
    }
    CoulombForces alone(settings, density, cloudBox), amongStrays(settings, density, cloudBox);
    alone.evaluate(inside);
    amongStrays.evaluate(withStrays);
    for (std::size_t i = 0; i < inside.size(); ++i)
        EXPECT_EQ(amongStrays.forces()[i], alone.forces()[i]) << "particle " << i;
    for (std::size_t i = inside.size(); i < withStrays.size(); ++i)
        EXPECT_EQ(amongStrays.forces()[i], Vec3::Zero()) << "stray " << i - inside.size();
    EXPECT_EQ(amongStrays.potentialEnergy(), alone.potentialEnergy());
}

TEST(CoulombForces, AreTheSameBitsForAnyThreadCountOrCloudOrder) {
    const CoulombSettings settings = shifted(1e-3);
    const ParticleCloud cloud = randomChargedCloud(600, 12);
    ParticleCloud reversed;
    for (std::size_t n = cloud.size(); n-- > 0;) {
        reversed.add(cloud.id[n], cloud.position[n], cloud.velocity[n], cloud.radius[n]);
        reversed.charge.push_back(cloud.charge[n]);
    }
    CoulombForces oneThread(settings, density, cloudBox), twoThreads(settings, density, cloudBox),
        backwards(settings, density, cloudBox);
    setThreads(1);
    oneThread.evaluate(cloud);
    setThreads(2);
    twoThreads.evaluate(cloud);
    backwards.evaluate(reversed);
    const std::size_t count = cloud.size();
    for (std::size_t i = 0; i < count; ++i) {
        EXPECT_EQ(twoThreads.forces()[i], oneThread.forces()[i]);
        EXPECT_EQ(backwards.forces()[count - 1 - i], oneThread.forces()[i]);
    }
}

/// A scene without gas: particles of R = 50 µm, ρp = 2500, charged (E = B = 0), Coulomb forces
/// truncated at cutoff.
Scene coulombScene(int count, double cutoff, double dt, double endTime) {
    Scene scene = test::singleParticleScene();
    scene.carrier.type = CarrierType::none;
    scene.fluid = {0, 0, 293.15};
    scene.particles.count = count;
    scene.physics.electromagnetic.model = ElectromagneticModel::lorentz;
    scene.physics.electromagnetic.coulomb = shifted(cutoff);
    scene.time.dt = dt;
    scene.time.endTime = endTime;
    return scene;
}

/// A cloud to start from (Stepper::resume), every particle already injected and charged.
void start(Stepper& stepper, ParticleCloud cloud) {
    RunCounters counters;
    counters.injected = static_cast<long>(cloud.size());
    stepper.resume(counters, std::move(cloud), {});
}

struct Orbit {
    double stepAngle;   ///< ω h
    double periodError; ///< relative
    double radiusError; ///< largest |r − d|/d
};

/// Charges ±1 pC at separation d = 1 mm (cut-off 1 m) set on their circular orbit, stepped for
/// ten periods of the closed form at stepsPerPeriod steps each.
Orbit circularOrbit(int stepsPerPeriod) {
    const double d = 1e-3, q = 1e-12, cutoff = 1.0, reducedMass = mass / 2;
    const double k = shifted(cutoff).coulombConstant();
    // Kepler's third law ω² = k q²/(μ d³) with the shift's factor 1 + 2d²/r_c² − 3d⁴/r_c⁴ (which
    // makes the period shorter by 1e-6 here).
    const double shift = 1 + 2 * d * d / (cutoff * cutoff) - 3 * std::pow(d / cutoff, 4);
    const double omega = std::sqrt(k * q * q * shift / (reducedMass * d * d * d));
    const double period = 2 * pi / omega;
    constexpr int periods = 10;
    const Scene scene = coulombScene(2, cutoff, period / stepsPerPeriod, periods * period);
    const NoGas vacuum;
    Stepper stepper(scene, vacuum);
    ParticleCloud cloud;
    cloud.add(0, Vec3(-d / 2, 0, 0), Vec3(0, -omega * d / 2, 0), radius);
    cloud.add(1, Vec3(d / 2, 0, 0), Vec3(0, omega * d / 2, 0), radius);
    cloud.charge = {q, -q};
    start(stepper, std::move(cloud));
    double angle = 0, radiusError = 0;
    Vec3 previous(d, 0, 0);
    while (!stepper.finished()) {
        stepper.step();
        const Vec3 separation = stepper.cloud().position[1] - stepper.cloud().position[0];
        angle += std::atan2(previous.cross(separation).z(), previous.dot(separation));
        radiusError = std::max(radiusError, std::abs(separation.norm() / d - 1));
        previous = separation;
    }
    EXPECT_NEAR(stepper.time(), periods * period, 1e-12 * period);
    return {omega * scene.time.dt, 2 * pi * periods / angle - 1, radiusError};
}

TEST(CoulombOrbit, KeepsKeplersPeriodAndRadiusToTheSecondOrderOfTheStep) {
    // Velocity Verlet's own circle of radius d turns by θ = 2 arcsin(ωh/2) a step, at the speed
    // d sin θ/h = ωd (1 − (ωh)²/8): started at ωd, the orbit is an ellipse of eccentricity
    // e = (ωh)²/4, whose farthest point is at d (1 + 2e), and whose period is longer by 3e/2
    // (Kepler, a = d (1 + e)) less the circle's (ωh)²/24: radius error (ωh)²/2, period error
    // (ωh)²/3, bounded over the periods (symplectic). Both to 5 % (the next order, (ωh)² ≈ 1e-2).
    const Orbit coarse = circularOrbit(64), fine = circularOrbit(128);
    for (const Orbit& orbit : {coarse, fine}) {
        std::printf("Coulomb orbit at ωh = %.4f: period error %.3e, radius error %.3e\n",
                    orbit.stepAngle, orbit.periodError, orbit.radiusError);
        const double h2 = orbit.stepAngle * orbit.stepAngle;
        EXPECT_NEAR(orbit.periodError / (h2 / 3), 1.0, 0.05);
        EXPECT_NEAR(orbit.radiusError / (h2 / 2), 1.0, 0.05);
    }
}

/// 64 particles of 1 pC on a 4×4×4 lattice of 0.5 mm at rest, cut-off 1 mm: the cloud pushes
/// itself apart, most pairs crossing the cut-off. Largest |E − E0|/E0 over steps steps of dt.
double expansionEnergyError(double dt, int steps) {
    const Scene scene = coulombScene(64, 1e-3, dt, steps * dt);
    const NoGas vacuum;
    Stepper stepper(scene, vacuum);
    ParticleCloud cloud;
    for (int n = 0; n < 64; ++n)
        cloud.add(static_cast<ParticleId>(n), 5e-4 * Vec3(n % 4, n / 4 % 4, n / 16), Vec3::Zero(),
                  radius);
    cloud.charge.assign(64, 1e-12);
    CoulombForces atStart(scene.physics.electromagnetic.coulomb, density, scene.domain);
    atStart.evaluate(cloud);
    const double initial = atStart.potentialEnergy(); // at rest
    start(stepper, std::move(cloud));
    double largest = 0;
    while (!stepper.finished()) {
        stepper.step();
        double kinetic = 0;
        for (const Vec3& v : stepper.cloud().velocity) kinetic += 0.5 * mass * v.squaredNorm();
        const double energy = kinetic + stepper.coulombForces()->potentialEnergy();
        largest = std::max(largest, std::abs(energy / initial - 1));
    }
    return largest;
}

TEST(CoulombCloud, KeepsItsEnergyToTheSecondOrderOfTheStep) {
    // Velocity Verlet keeps a modified energy: E is off by O((h/τ)²), τ = √(m s³/(k q²)) = 4.3 ms
    // the lattice's time scale (s = 0.5 mm), bounded, not drifting, also as pairs cross the cut-off
    // (the force is continuous there, Eq. 2.97). Bound (h/τ)² (measured: 0.57 (h/τ)²); halving
    // h quarters the error (a plain cut-off's energy jumps would not shrink so).
    const double k = shifted(1e-3).coulombConstant(), q = 1e-12, s = 5e-4;
    const double tau = std::sqrt(mass * s * s * s / (k * q * q));
    const double coarse = expansionEnergyError(2e-4, 1000), fine = expansionEnergyError(1e-4, 2000);
    std::printf("Coulomb cloud energy error: %.3e at dt 2e-4 s, %.3e at 1e-4 s (τ %.3g s)\n",
                coarse, fine, tau);
    EXPECT_LT(coarse, std::pow(2e-4 / tau, 2));
    EXPECT_NEAR(coarse / fine, 4.0, 0.5);
}

/// 300 particles of randomChargedCloud (cut-off 1 mm) stepped 100 times on threads threads,
/// restarted (a new stepper from the state a checkpoint holds) after restartAfter steps.
ParticleCloud chargedCloudRun(int threads, int restartAfter = -1) {
    setThreads(threads);
    const Scene scene = coulombScene(300, 1e-3, 1e-4, 1e-2);
    const NoGas vacuum;
    auto stepper = std::make_unique<Stepper>(scene, vacuum);
    start(*stepper, randomChargedCloud(300, 13));
    for (int n = 0; n < 100; ++n) {
        if (n == restartAfter) {
            auto resumed = std::make_unique<Stepper>(scene, vacuum);
            resumed->resume(stepper->counters(), stepper->cloud(), stepper->arrivals());
            stepper = std::move(resumed);
        }
        stepper->step();
    }
    setThreads(2);
    return stepper->cloud();
}

TEST(CoulombCloud, IsTheSameForAnyThreadCountOrRestart) {
    const ParticleCloud oneThread = chargedCloudRun(1);
    for (const ParticleCloud& other : {chargedCloudRun(2), chargedCloudRun(2, 50)}) {
        EXPECT_EQ(other.position, oneThread.position);
        EXPECT_EQ(other.velocity, oneThread.velocity);
    }
    // The charges moved: the test compares a run, not the start.
    const ParticleCloud initial = randomChargedCloud(300, 13);
    double moved = 0;
    for (std::size_t i = 0; i < initial.size(); ++i)
        moved = std::max(moved, (oneThread.position[i] - initial.position[i]).norm());
    EXPECT_GT(moved, 1e-6);
}

TEST(CoulombTimeStep, IsATenthOfTheTouchingPairsTimeScale) {
    // 1 nC on R = 50 µm: τ = √(m (2R)³/(k q²)) = 3.8e-7 s, far below the other limits of a
    // particle in a uniform 10 m/s stream.
    Scene scene = test::singleParticleScene();
    scene.physics.electromagnetic.model = ElectromagneticModel::lorentz;
    scene.physics.electromagnetic.chargeValue = 1e-9;
    scene.physics.electromagnetic.coulomb = shifted(1e-3);
    scene.time.dt = 0;
    scene.time.endTime = 1e-2;
    const test::UniformFlow gas(Vec3(10, 0, 0));
    const SceneAnalysis analysis = analyseScene(scene, gas);
    const double tau =
        std::sqrt(mass * std::pow(2 * radius, 3) / (shifted(1e-3).coulombConstant() * 1e-9 * 1e-9));
    EXPECT_NEAR(tau, 3.82e-7, 0.01e-7);
    EXPECT_EQ(analysis.timeStepLimitedBy, "coulombTime");
    // Rounded down to two digits: at most 10 % below.
    EXPECT_LE(analysis.suggestedTimeStep, tau / stepsPerCoulombTime);
    EXPECT_GT(analysis.suggestedTimeStep, 0.9 * tau / stepsPerCoulombTime);
}

} // namespace
} // namespace slides
