// ctest-labels: foundation physics carrier
// The SIMD kernels against their scalar references, over many random particles: the exact drag
// relaxation (integrate/relaxation_batch.h against relaxExactly with dragResponseTime) and the
// response times alone (physics/drag_response.h), every drag law of Eq. 3.16–3.17 and its
// kin, Re from 0 past the 1000 switch; the sech² jet's
// velocity (carrier/bickley_batch.h against JetFrame::sample with BickleyProfile::at,
// Eq. 5.10/5.11: behind the exit, in the core, on the axis, far out). Tolerance: each result is
// a chain of about ten operations, each within 4 ulp in Highway's maths (expm1, log) and ½ ulp
// otherwise, so within ~40 ulp ≈ 1e-14 of the largest term it sums; 1e-13 of that term leaves a
// margin of ten. Both kernels give each particle the same bits whatever the batch's split or
// the thread count. The eddy-interaction step (integrate/eddy_batch.h against
// eddyInteractionStep, physics/dispersion.h; Gosman & Ioannides 1983) agrees with its scalar
// reference, step by step from the same state over twenty steps of particles that stay in their
// eddy, start one, cross one, or see laminar, broken or long-step gas: the random draws and the
// lifetime left exactly, ū' to 1e-13 of σ, the eddy length left to 1e-13 of l_e.
#include "slides/carrier/analytic_jet.h"
#include "slides/carrier/bickley_batch.h"
#include "slides/integrate/eddy_batch.h"
#include "slides/integrate/integrator.h"
#include "slides/integrate/relaxation_batch.h"
#include "slides/physics/drag_response.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace slides {
namespace {

constexpr double tolerance = 1e-13;
constexpr std::size_t particleCount = 4099; // not a multiple of any vector width

struct Particles {
    std::vector<Vec3> x, v, u, w;
    std::vector<double> radius, h;
};

/// Radii 1 µm – 300 µm, slips 0 – 150 m/s (Re up to ~6000 in air), steps 0.01–1000 τ-ish.
Particles randomParticles(std::uint32_t seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(-1, 1), logUniform(0, 1);
    Particles p;
    for (std::size_t i = 0; i < particleCount; ++i) {
        const Vec3 direction = Vec3(unit(random), unit(random), unit(random)).normalized();
        p.x.push_back(Vec3(unit(random), unit(random), unit(random)) * 0.05);
        p.v.push_back(Vec3(unit(random), unit(random), unit(random)) * 30);
        const double slip = i % 7 == 0 ? 0.0 : 150 * std::pow(logUniform(random), 2);
        p.u.push_back(p.v.back() + slip * direction);
        p.w.push_back(i % 3 == 0 ? p.v.back() : Vec3(p.u.back() - 2 * slip * direction));
        p.radius.push_back(1e-6 * std::pow(300, logUniform(random)));
        p.h.push_back(1e-7 * std::pow(1e4, logUniform(random)));
    }
    return p;
}

class RelaxationKernel : public testing::TestWithParam<DragModel> {};

TEST_P(RelaxationKernel, MatchesScalarRelaxExactly) {
    const DragParameters drag{GetParam(), 1.2, 1.5e-5, 5680};
    const Vec3 a(0.3, -9.81, 0.2);
    const double fraction = 0.5;
    Particles scalar = randomParticles(7);
    Particles simd = scalar;
    relaxBatchExactly({simd.x, simd.v, simd.x, simd.v, simd.u, simd.w, simd.radius, simd.h}, drag,
                      a, fraction);
    double largestReynolds = 0;
    for (std::size_t i = 0; i < particleCount; ++i) {
        const double slip = (scalar.u[i] - scalar.w[i]).norm();
        largestReynolds = std::max(
            largestReynolds, particleReynolds(slip, scalar.radius[i], drag.kinematicViscosity));
        const double tau = dragResponseTime(drag, scalar.radius[i], slip);
        const double h = fraction * scalar.h[i];
        const double speedScale = scalar.v[i].norm() + scalar.u[i].norm() + tau * a.norm();
        relaxExactly(scalar.x[i], scalar.v[i], scalar.u[i], tau, a, h);
        EXPECT_LE((simd.v[i] - scalar.v[i]).norm(), tolerance * speedScale) << "particle " << i;
        EXPECT_LE((simd.x[i] - scalar.x[i]).norm(),
                  tolerance * (scalar.x[i].norm() + speedScale * h))
            << "particle " << i;
    }
    EXPECT_GT(largestReynolds, 1000) << "the laws' switch at Re = 1000 is covered";
}

TEST_P(RelaxationKernel, ResponseTimesMatchScalarDragResponseTime) {
    const DragParameters drag{GetParam(), 1.2, 1.5e-5, 5680};
    const Particles p = randomParticles(13);
    std::vector<double> slip, tau(particleCount);
    for (std::size_t i = 0; i < particleCount; ++i) slip.push_back((p.u[i] - p.w[i]).norm());
    dragResponseTimes(drag, p.radius, slip, tau);
    for (std::size_t i = 0; i < particleCount; ++i) {
        const double expected = dragResponseTime(drag, p.radius[i], slip[i]);
        EXPECT_LE(std::abs(tau[i] - expected), tolerance * expected) << "particle " << i;
    }
}

INSTANTIATE_TEST_SUITE_P(EveryDragLaw, RelaxationKernel,
                         testing::Values(DragModel::stokes, DragModel::schillerNaumann,
                                         DragModel::haiderLevenspiel, DragModel::putnam));

TEST(RelaxationKernel, SameBitsForAnySplitAndThreadCount) {
    const DragParameters drag{DragModel::haiderLevenspiel, 1.2, 1.5e-5, 5680};
    const Vec3 a(0, -9.81, 0);
    const Particles start = randomParticles(11);
    Particles whole = start, split = start, twoThreads = start;
    relaxBatchExactly({whole.x, whole.v, whole.x, whole.v, whole.u, whole.w, whole.radius, whole.h},
                      drag, a, 1);
    const auto relaxRange = [&](Particles& p, std::size_t first, std::size_t count) {
        relaxBatchExactly(
            {std::span(p.x).subspan(first, count), std::span(p.v).subspan(first, count),
             std::span(p.x).subspan(first, count), std::span(p.v).subspan(first, count),
             std::span(p.u).subspan(first, count), std::span(p.w).subspan(first, count),
             std::span(p.radius).subspan(first, count), std::span(p.h).subspan(first, count)},
            drag, a, 1);
    };
    relaxRange(split, 0, 3); // a batch smaller than a vector, then one starting mid-vector
    relaxRange(split, 3, particleCount - 3);
    const int threads = omp_get_max_threads();
    omp_set_num_threads(2);
    relaxRange(twoThreads, 0, particleCount);
    omp_set_num_threads(threads);
    for (std::size_t i = 0; i < particleCount; ++i) {
        EXPECT_EQ(whole.x[i], split.x[i]) << "particle " << i;
        EXPECT_EQ(whole.v[i], split.v[i]) << "particle " << i;
        EXPECT_EQ(whole.x[i], twoThreads.x[i]) << "particle " << i;
        EXPECT_EQ(whole.v[i], twoThreads.v[i]) << "particle " << i;
    }
}

TEST(RelaxationKernel, NonFiniteGasGivesNonFiniteState) {
    const DragParameters drag{DragModel::haiderLevenspiel, 1.2, 1.5e-5, 5680};
    Particles p = randomParticles(3);
    p.u[5] = Vec3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
    relaxBatchExactly({p.x, p.v, p.x, p.v, p.u, p.w, p.radius, p.h}, drag, Vec3(0, -9.81, 0), 1);
    EXPECT_FALSE(p.x[5].allFinite());
    EXPECT_FALSE(p.v[5].allFinite());
    EXPECT_TRUE(p.x[4].allFinite() && p.x[6].allFinite()) << "lanes stay independent";
}

/// Particles in turbulence for the eddy step: k from 0.1 to 10 m²/s² and T_L from 1e-5 to
/// 1e-2 s (log-uniform; so the 1e-5 s steps end eddies often and rarely, by lifetime and by
/// crossing), with laminar (k = 0), broken (ε NaN) and long steps (h = 1e-3 s, beyond 50 T_L
/// where T_L < 2e-5 s) among them; slips up to 3.5 m/s.
struct Turbulent {
    std::vector<EddyState> eddy;
    std::vector<ParticleId> id;
    std::vector<Vec3> v, u, fluctuation;
    std::vector<double> k, epsilon, radius, h;

    EddyBatch batch(std::size_t first, std::size_t count) {
        const auto part = [&](auto& array) { return std::span(array).subspan(first, count); };
        return {part(eddy),    part(id),     part(v), part(u),          part(k),
                part(epsilon), part(radius), part(h), part(fluctuation)};
    }
};

Turbulent turbulentParticles(std::uint32_t seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(-1, 1), logUniform(0, 1);
    Turbulent p;
    for (std::size_t i = 0; i < particleCount; ++i) {
        p.eddy.push_back({});
        p.id.push_back(1000 + i);
        p.v.push_back(Vec3(unit(random), unit(random), unit(random)));
        p.u.push_back(Vec3(unit(random), unit(random), unit(random)));
        p.fluctuation.push_back(Vec3::Zero());
        const double k = 0.1 * std::pow(100, logUniform(random));
        const double lagrangianTime = 1e-5 * std::pow(1e3, logUniform(random));
        p.k.push_back(i % 11 == 0 ? 0.0 : k);
        p.epsilon.push_back(i % 13 == 0 ? std::numeric_limits<double>::quiet_NaN()
                                        : 1.5 * 0.09 / 0.7 * k / lagrangianTime); // T_L
        p.radius.push_back(1e-6 * std::pow(100, logUniform(random)));
        p.h.push_back(i % 17 == 0 ? 1e-3 : 1e-5);
    }
    return p;
}

TEST(EddyKernel, MatchesScalarEddyInteractionStep) {
    const DragParameters drag{DragModel::putnam, 1.2, 1.5e-5, 2500};
    const Vec3 a(0.3, -9.81, 0.2);
    const DispersionConstants constants;
    const std::uint64_t seed = 3;
    Turbulent simd = turbulentParticles(9);
    long inLanes = 0, newEddies = 0;
    for (int step = 0; step < 20; ++step) {
        const std::vector<EddyState> before = simd.eddy;
        std::vector<EddyState> scalar = simd.eddy;
        eddyInteractionBatch(simd.batch(0, particleCount), constants, drag, a, seed);
        for (std::size_t i = 0; i < particleCount; ++i) {
            const Vec3 slip = simd.v[i] - simd.u[i];
            const ParticleResponse particle{slip,
                                            dragResponseTime(drag, simd.radius[i], slip.norm()), a};
            const Vec3 expected =
                eddyInteractionStep(scalar[i], constants, simd.k[i], simd.epsilon[i], particle,
                                    simd.h[i], RandomKey{seed, simd.id[i]});
            ASSERT_EQ(simd.eddy[i].count, scalar[i].count) << "particle " << i << " step " << step;
            EXPECT_EQ(simd.eddy[i].standardised, scalar[i].standardised) << "particle " << i;
            if (!expected.allFinite()) {
                EXPECT_FALSE(simd.fluctuation[i].allFinite()) << "particle " << i;
                continue;
            }
            const double sigma = fluctuationRms(simd.k[i]);
            EXPECT_LE((simd.fluctuation[i] - expected).norm(),
                      tolerance * sigma * (1 + expected.norm() / std::max(sigma, 1e-300)))
                << "particle " << i << " step " << step;
            EXPECT_EQ(simd.eddy[i].timeLeft, scalar[i].timeLeft) << "particle " << i;
            const double eddyLength = eddyLengthScale(constants, simd.k[i], simd.epsilon[i]);
            EXPECT_LE(std::abs(simd.eddy[i].lengthLeft - scalar[i].lengthLeft),
                      tolerance * eddyLength)
                << "particle " << i << " step " << step;
            newEddies += scalar[i].count != before[i].count;
            inLanes += simd.k[i] > 0 && scalar[i].count == before[i].count;
        }
    }
    EXPECT_GT(inLanes, 5 * static_cast<long>(particleCount)) << "a quarter stay in their eddy";
    EXPECT_GT(newEddies, static_cast<long>(particleCount)) << "and many begin a new one";
}

TEST(EddyKernel, SameBitsForAnySplitAndThreadCount) {
    const DragParameters drag{DragModel::haiderLevenspiel, 1.2, 1.5e-5, 5680};
    const Vec3 a(0, -9.81, 0);
    const DispersionConstants constants;
    Turbulent whole = turbulentParticles(4), split = whole, twoThreads = whole;
    const int threads = omp_get_max_threads();
    for (int step = 0; step < 5; ++step) {
        eddyInteractionBatch(whole.batch(0, particleCount), constants, drag, a, 1);
        // A batch smaller than a vector, then one starting mid-vector.
        eddyInteractionBatch(split.batch(0, 3), constants, drag, a, 1);
        eddyInteractionBatch(split.batch(3, particleCount - 3), constants, drag, a, 1);
        omp_set_num_threads(2);
        eddyInteractionBatch(twoThreads.batch(0, particleCount), constants, drag, a, 1);
        omp_set_num_threads(threads);
    }
    for (std::size_t i = 0; i < particleCount; ++i) {
        for (const Turbulent* other : {&split, &twoThreads}) {
            EXPECT_EQ(std::memcmp(&whole.fluctuation[i], &other->fluctuation[i], sizeof(Vec3)), 0)
                << "particle " << i;
            EXPECT_EQ(whole.eddy[i].standardised, other->eddy[i].standardised) << "particle " << i;
            EXPECT_EQ(whole.eddy[i].timeLeft, other->eddy[i].timeLeft) << "particle " << i;
            EXPECT_EQ(whole.eddy[i].lengthLeft, other->eddy[i].lengthLeft) << "particle " << i;
            EXPECT_EQ(whole.eddy[i].count, other->eddy[i].count) << "particle " << i;
        }
    }
}

class JetKernel : public testing::TestWithParam<JetGeometry> {};

TEST_P(JetKernel, MatchesScalarProfile) {
    JetNozzle nozzle;
    nozzle.centre = Vec3(0.01, -0.02, 0.005);
    nozzle.axis = Vec3(1, 2, 2) / 3.0; // oblique, so no component is special
    nozzle.radius = 2e-3;
    nozzle.crossSpanDirection = Vec3(2, -2, 1) / 3.0;
    AnalyticJetParameters parameters;
    parameters.profile = GetParam();
    parameters.nozzleVelocity = 25;
    parameters.viscosity = 1.4e-3;
    parameters.coreLength = 8e-3;
    const AnalyticJet jet(nozzle, parameters);
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> axial(-0.01, 0.1), across(-0.03, 0.03);
    std::vector<Vec3> points;
    for (std::size_t i = 0; i < particleCount; ++i) {
        const Vec3 offset(across(random), across(random), across(random));
        const Vec3 transverse = i % 5 == 0 ? Vec3::Zero() // on the axis
                                           : Vec3(offset - offset.dot(nozzle.axis) * nozzle.axis);
        points.push_back(nozzle.centre + axial(random) * nozzle.axis + transverse);
    }
    CarrierSample reference;
    jet.frame().sample(jet.profile(), points, {.velocityGradient = true}, reference);
    std::vector<Vec3> velocity(points.size());
    sampleBickleyVelocity(jet.frame(), jet.profile(), points, velocity);
    int behind = 0, core = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double a = (points[i] - nozzle.centre).dot(nozzle.axis);
        behind += a < 0;
        core += a >= 0 && a < parameters.coreLength;
        EXPECT_LE((velocity[i] - reference.velocity[i]).norm(),
                  tolerance * jet.centrelineVelocity(std::max(a, 0.0)))
            << "point " << i << " at axial distance " << a;
    }
    EXPECT_GT(behind, 100);
    EXPECT_GT(core, 100);
}

INSTANTIATE_TEST_SUITE_P(BothGeometries, JetKernel,
                         testing::Values(JetGeometry::planar, JetGeometry::axisymmetric));

} // namespace
} // namespace slides
