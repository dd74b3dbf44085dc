// ctest-labels: electromagnetic physics
// Charged particles in uniform electric and magnetic fields (Section 2.7.1, Eq. 2.93; the exact
// flow of integrate/lorentz_flow.h), each against its closed form:
//  - gyration in a uniform B: Larmor radius |v⊥|/ω and period 2π/ω, to 1e-8 over 100 periods
//    at 37 steps a period (the flow is exact: no spiralling out, no phase drift);
//  - crossed E and B: the guiding centre drifts at |E|/|B| along E × B (a cycloid), 1e-8 over
//    100 periods;
//  - E along B: uniform acceleration qE/m, x = ½ g t²;
//  - Stokes drag: the terminal drift v = (λ f + f × Ω)/(λ² + ω²), f = qE/m + λu (the steady
//    state of dv/dt = f − λv + v × Ω), reached at any step, and the flow against a fine RK4
//    integration of the same equation (an independent check of the closed form);
//  - through the stepper: the Larmor orbit of a particle charged by either charge model;
//  - bipolar charging: a fraction of the particles charged −value, each sign drawn from the
//    particle's id (the count of each sign within the binomial bound), and a bipolar cloud in a
//    uniform E parting along ±E as x = ½ (qE/m) t², the same at 1 and 2 threads.
#include "../support/test_scenes.h"
#include "slides/carrier/no_gas.h"
#include "slides/integrate/lorentz_flow.h"
#include "slides/physics/electromagnetic.h"
#include "slides/run/stepper.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <omp.h>

namespace slides {
namespace {

constexpr double pi = std::numbers::pi;

TEST(LorentzFlow, GyratesOnTheLarmorCircleWithItsPeriod) {
    // Ω = (0 0 ω), v0 = (v 0 0): dv/dt = v × Ω turns v towards −y; centre (0, −v/ω, 0).
    const double omega = 2.3e3, speed = 4.0, radius = speed / omega;
    const Vec3 gyration(0, 0, omega), centre(0, -radius, 0);
    const int stepsPerPeriod = 37, periods = 100;
    const double h = 2 * pi / omega / stepsPerPeriod;
    Vec3 x = Vec3::Zero(), v(speed, 0, 0);
    for (int step = 1; step <= stepsPerPeriod * periods; ++step) {
        flowInFields(x, v, Vec3::Zero(), 0.0, Vec3::Zero(), gyration, h);
        // Exact up to round-off growing with the step count: 1e-8 leaves 1e5 ulp.
        ASSERT_NEAR((x - centre).norm() / radius, 1.0, 1e-8) << "step " << step;
        ASSERT_NEAR(v.norm() / speed, 1.0, 1e-8) << "step " << step;
    }
    // After 100 periods, back at the start (the period is 2π/ω).
    EXPECT_LT(x.norm() / radius, 1e-8);
    EXPECT_LT((v - Vec3(speed, 0, 0)).norm() / speed, 1e-8);
}

TEST(LorentzFlow, CrossedFieldsDriftAtEOverB) {
    // E = (0 E 0), B = (0 0 B): from rest a cycloid whose guiding centre moves at E/B along
    // E × B = +x; after whole periods the particle is back on y = 0, at x = (E/B) t.
    const double chargeToMass = 1e-3, electric = 2e4, magnetic = 0.7;
    const double omega = chargeToMass * magnetic, drift = electric / magnetic;
    const Vec3 g(0, chargeToMass * electric, 0), gyration(0, 0, omega);
    const int stepsPerPeriod = 25, periods = 100;
    const double period = 2 * pi / omega, h = period / stepsPerPeriod;
    Vec3 x = Vec3::Zero(), v = Vec3::Zero();
    for (int step = 0; step < stepsPerPeriod * periods; ++step)
        flowInFields(x, v, Vec3::Zero(), 0.0, g, gyration, h);
    const double travelled = drift * periods * period;
    EXPECT_NEAR(x.x() / travelled, 1.0, 1e-8);
    EXPECT_LT(std::abs(x.y()) / travelled, 1e-8);
    EXPECT_LT(v.norm() / drift, 1e-8); // at rest again at the cycloid's cusps
}

TEST(LorentzFlow, AcceleratesUniformlyAlongTheMagneticField) {
    const Vec3 gyration = Vec3(1, 2, -2) / 3 * 50.0; // |Ω| = 50 rad/s
    const Vec3 g = 7.0 * gyration.normalized();
    Vec3 x = Vec3::Zero(), v = Vec3::Zero();
    for (int step = 0; step < 40; ++step) flowInFields(x, v, Vec3::Zero(), 0.0, g, gyration, 0.025);
    EXPECT_LT((v - g * 1.0).norm() / 7.0, 1e-13);
    EXPECT_LT((x - 0.5 * g).norm() / 3.5, 1e-13);
}

/// dv/dt = g + λ(u − v) + v × Ω by classical RK4, n steps over h.
void rungeKutta(Vec3& x, Vec3& v, const Vec3& u, double lambda, const Vec3& g, const Vec3& w,
                double h, int n) {
    const auto dv = [&](const Vec3& velocity) {
        return Vec3(g + lambda * (u - velocity) + velocity.cross(w));
    };
    const double k = h / n;
    for (int i = 0; i < n; ++i) {
        const Vec3 a1 = dv(v), b1 = v;
        const Vec3 a2 = dv(v + 0.5 * k * a1), b2 = v + 0.5 * k * a1;
        const Vec3 a3 = dv(v + 0.5 * k * a2), b3 = v + 0.5 * k * a2;
        const Vec3 a4 = dv(v + k * a3), b4 = v + k * a3;
        x += k / 6 * (b1 + 2 * b2 + 2 * b3 + b4);
        v += k / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
    }
}

TEST(LorentzFlow, MatchesAFineRungeKuttaIntegration) {
    // Oblique fields, gas flow and drag: every term of the flow at once; RK4 with 2·10⁴
    // steps a flow step is converged to ~1e-14 (error ∝ (k·max(λ, ω))⁴ ≈ 1e-16).
    const Vec3 u(0.3, -1.2, 0.5), g(2.0, 0.5, -9.81), gyration(40.0, -25.0, 60.0);
    for (const double lambda : {0.0, 1.0, 80.0}) {
        for (const double h : {1e-3, 0.02, 0.3}) {
            Vec3 x(0.1, 0.2, 0.3), v(1.0, 2.0, -0.5);
            Vec3 xr = x, vr = v;
            flowInFields(x, v, u, lambda, g, gyration, h);
            rungeKutta(xr, vr, u, lambda, g, gyration, h, 20000);
            EXPECT_LT((v - vr).norm() / vr.norm(), 1e-11) << "λ " << lambda << ", h " << h;
            EXPECT_LT((x - xr).norm() / xr.norm(), 1e-11) << "λ " << lambda << ", h " << h;
        }
    }
}

TEST(LorentzFlow, ReachesTheTerminalDriftOfStokesDragAtAnyStep) {
    // Steady state of dv/dt = f − λv + v × Ω with f ⊥ Ω: v = (λ f + f × Ω)/(λ² + ω²). For
    // f = (f 0 0), Ω = (0 0 ω): v = (λ f, −ω f, 0)/(λ² + ω²) (the drift turns from E towards
    // −E × B ... the Hall angle atan(ω/λ)).
    const double lambda = 250.0, omega = 400.0, force = 3.0;
    const Vec3 g(force, 0, 0), gyration(0, 0, omega);
    const Vec3 terminal =
        Vec3(lambda * force, -omega * force, 0) / (lambda * lambda + omega * omega);
    for (const double h : {1e-4, 1e-2, 1.0}) { // h λ from 0.025 to 250
        Vec3 x = Vec3::Zero(), v = Vec3::Zero();
        const int steps = static_cast<int>(std::ceil(0.2 / h)); // 50 response times
        for (int step = 0; step < steps; ++step)
            flowInFields(x, v, Vec3::Zero(), lambda, g, gyration, h);
        EXPECT_LT((v - terminal).norm() / terminal.norm(), 1e-12) << "h " << h;
    }
}

TEST(LorentzFlow, SeriesAndClosedFormAgreeWhereTheySwitch) {
    // φ and ψ switch from series to closed form at |y| = 0.5: both sides agree to round-off,
    // and the flow is continuous in λ and ω there.
    const Vec3 u(1, 0, 0), g(0, 1, 0);
    for (const Vec3& direction : {Vec3(1, 0, 0), Vec3(0, 0, 1)}) {
        Vec3 xBelow = Vec3::Zero(), vBelow(0, 0, 1), xAbove = xBelow, vAbove = vBelow;
        const double below = std::nextafter(0.5, 0.0), above = std::nextafter(0.5, 1.0);
        // direction x: a drag rate λh crossing 0.5; z: a gyration angle ωh crossing 0.5.
        const bool drag = direction.x() > 0;
        flowInFields(xBelow, vBelow, u, drag ? below : 0.0, g,
                     drag ? Vec3::Zero() : Vec3(direction * below), 1.0);
        flowInFields(xAbove, vAbove, u, drag ? above : 0.0, g,
                     drag ? Vec3::Zero() : Vec3(direction * above), 1.0);
        EXPECT_LT((vBelow - vAbove).norm(), 1e-14);
        EXPECT_LT((xBelow - xAbove).norm(), 1e-14);
    }
}

TEST(ChargeModels, FixedOrProportionalToTheSurface) {
    ElectromagneticSettings settings;
    settings.model = ElectromagneticModel::lorentz;
    settings.chargeValue = 2e-6;
    EXPECT_EQ(settings.chargeOf(1e-5, 17), 2e-6);
    settings.charge = ChargeModel::surface;
    EXPECT_NEAR(settings.chargeOf(1e-5, 17), 2e-6 * 4 * pi * 1e-10, 1e-30);
    EXPECT_FALSE(ElectromagneticSettings{}.on());
}

TEST(ChargeModels, AFractionOfTheParticlesCarriesTheOppositeSign) {
    ElectromagneticSettings settings;
    settings.model = ElectromagneticModel::lorentz;
    settings.chargeValue = -3e-12; // the value's sign is the majority's
    settings.seed = 11;
    const int count = 40000;
    for (const double fraction : {0.0, 0.3, 0.5, 1.0}) {
        settings.oppositeSignFraction = fraction;
        int opposite = 0;
        for (ParticleId id = 0; id < count; ++id) {
            const double q = settings.chargeOf(20e-6, id);
            ASSERT_EQ(std::abs(q), 3e-12);
            ASSERT_EQ(q, settings.chargeOf(20e-6, id)) << "a particle's sign is its id's";
            opposite += q > 0;
        }
        // Binomial: mean N f, standard deviation √(N f (1 − f)) (≤ 100 here); 5σ.
        const double sigma = std::sqrt(count * fraction * (1 - fraction));
        EXPECT_NEAR(opposite, count * fraction, 5 * sigma + 1e-9) << "fraction " << fraction;
    }
    // Another seed draws other signs (about half of them differ at f = 0.5).
    settings.oppositeSignFraction = 0.5;
    ElectromagneticSettings reseeded = settings;
    reseeded.seed = 12;
    int differ = 0;
    for (ParticleId id = 0; id < count; ++id)
        differ += settings.chargeOf(20e-6, id) != reseeded.chargeOf(20e-6, id);
    EXPECT_NEAR(differ, count / 2, 5 * std::sqrt(count / 4.0));
}

/// One particle (R = 50 µm, ρp = 2500) injected at rest at the origin, charged σ 4πR² with
/// σ = 1e-4 C/m², in E = (0 E 0), B = (0 0 B).
Scene chargedParticleScene(double electric, double magnetic) {
    Scene scene = test::singleParticleScene();
    ElectromagneticSettings& fields = scene.physics.electromagnetic;
    fields.model = ElectromagneticModel::lorentz;
    fields.electricField = Vec3(0, electric, 0);
    fields.magneticField = Vec3(0, 0, magnetic);
    fields.charge = ChargeModel::surface;
    fields.chargeValue = 1e-4;
    return scene;
}

double chargeToMass(const Scene& scene) {
    const double radius = scene.particles.radius.value;
    return scene.physics.electromagnetic.chargeOfModel(radius) /
           (4.0 / 3.0 * pi * radius * radius * radius * scene.particles.density);
}

TEST(ChargedParticleRun, DriftsAtEOverBWithoutGas) {
    // carrier none: the stepper's flight is the flow without drag; from rest, a cycloid whose
    // centre moves at E/B: after 100 periods at rest on y = 0, x = (E/B) t (to 1e-8).
    const double electric = 1.0, magnetic = 2.0, drift = electric / magnetic;
    Scene scene = chargedParticleScene(electric, magnetic);
    scene.carrier.type = CarrierType::none;
    const double period = 2 * pi / (chargeToMass(scene) * magnetic);
    scene.time.dt = period / 30;
    scene.time.endTime = 100 * period;
    const NoGas gas;
    Stepper stepper(scene, gas);
    while (!stepper.finished()) stepper.step();
    const ParticleCloud& cloud = stepper.cloud();
    ASSERT_EQ(cloud.size(), 1u);
    EXPECT_NEAR(cloud.charge.at(0), 1e-4 * 4 * pi * 2.5e-9, 1e-25); // σ 4πR², R = 50 µm
    const double travelled = drift * stepper.time();
    EXPECT_NEAR(cloud.position[0].x() / travelled, 1.0, 1e-8);
    EXPECT_LT(std::abs(cloud.position[0].y()) / travelled, 1e-8);
    EXPECT_LT(cloud.velocity[0].norm() / drift, 1e-8);
}

TEST(ChargedParticleRun, ABipolarCloudPartsAlongTheElectricField) {
    // 2000 particles at rest at the origin, no gas, E = (0 E 0): each moves y = ½ (qE/m) t²,
    // up for +q, down for −q, its charge the one its id draws; the same at 1 and 2 threads.
    Scene scene = chargedParticleScene(1.0, 0.0);
    scene.carrier.type = CarrierType::none;
    scene.particles.count = 2000;
    scene.physics.electromagnetic.oppositeSignFraction = 0.4;
    scene.physics.electromagnetic.seed = scene.injection.seed;
    scene.time.dt = 1e-3;
    scene.time.endTime = 0.05;
    const double g = chargeToMass(scene) * 1.0; // |q|E/m
    std::vector<ParticleCloud> clouds;
    for (const int threads : {1, 2}) {
        omp_set_num_threads(threads);
        const NoGas gas;
        Stepper stepper(scene, gas);
        while (!stepper.finished()) stepper.step();
        clouds.push_back(stepper.cloud());
    }
    omp_set_num_threads(omp_get_num_procs());
    const ParticleCloud& cloud = clouds[0];
    ASSERT_EQ(cloud.size(), 2000u);
    const double t = scene.time.endTime, travelled = 0.5 * g * t * t;
    int down = 0;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const double q = scene.physics.electromagnetic.chargeOf(50e-6, cloud.id[i]);
        ASSERT_EQ(cloud.charge[i], q);
        const double sign = q > 0 ? 1.0 : -1.0;
        // The start lies within the nozzle's 1e-15 m of the origin (3e-10 of the way).
        ASSERT_NEAR(cloud.position[i].y(), sign * travelled, 1e-12 * travelled + 1e-15)
            << "particle " << i;
        down += q < 0;
    }
    EXPECT_NEAR(down, 800, 5 * std::sqrt(2000 * 0.4 * 0.6)); // about 40 % charged −value
    EXPECT_EQ(clouds[1].charge, cloud.charge);
    EXPECT_EQ(clouds[1].position, cloud.position);
}

TEST(ChargedParticleRun, ReachesTheStokesTerminalDriftInUniformGas) {
    // Stokes drag in gas at u = (0 0.5 0.2): the steady state of dv/dt = qE/m + (u − v)/τ +
    // v × Ω is v = u∥ + (λ f + f × Ω)/(λ² + ω²) across B, f = qE/m + λu⊥, reached after 40 τ
    // (e^(−40) ≈ 4e-18) at steps of τ/3 and 3τ. The fields give ωτ = 1 and qEτ/m = 1 m/s (far
    // beyond what a gas holds: a 45° Hall angle tests the coupling of drag and gyration).
    for (const double stepsPerTau : {3.0, 1.0 / 3.0}) {
        Scene scene = chargedParticleScene(0, 0);
        scene.physics.drag = DragModel::stokes;
        const double tau = stokesResponseTime(scene.particles.density, scene.particles.radius.value,
                                              scene.fluid.density, scene.fluid.kinematicViscosity);
        const double field = 1 / (tau * chargeToMass(scene)); // E [V/m] and B [T] alike
        scene.physics.electromagnetic.electricField = Vec3(0, field, 0);
        scene.physics.electromagnetic.magneticField = Vec3(0, 0, field);
        scene.time.dt = tau / stepsPerTau;
        scene.time.endTime = 40 * tau;
        const Vec3 u(0, 0.5, 0.2);
        const test::UniformFlow gas(u);
        Stepper stepper(scene, gas);
        while (!stepper.finished()) stepper.step();
        const double lambda = 1 / tau;
        const Vec3 f = Vec3(0, lambda, 0) + lambda * Vec3(u.x(), u.y(), 0); // qE/m = (0 1/τ 0)
        const Vec3 gyration(0, 0, lambda);                                  // ω = 1/τ
        const Vec3 terminal = Vec3(0, 0, u.z()) + (lambda * f + f.cross(gyration)) /
                                                      (lambda * lambda + lambda * lambda);
        EXPECT_LT((stepper.cloud().velocity.at(0) - terminal).norm() / terminal.norm(), 1e-10)
            << "steps of τ/" << stepsPerTau;
    }
}

} // namespace
} // namespace slides
