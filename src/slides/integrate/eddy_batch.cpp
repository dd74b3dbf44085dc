#include "slides/integrate/eddy_batch.h"

// Compiled once per instruction set (Highway's foreach_target), dispatched at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "slides/integrate/eddy_batch.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include "slides/core/simd_math-inl.h"
#include "slides/physics/drag_response-inl.h"

#include <hwy/highway.h>

#include <array>
#include <limits>

namespace slides {
/// The scalar reference step of particle i, compiled once for the baseline instruction set (as
/// the scalar step of physics/dispersion.cpp is), so its bits do not depend on the SIMD target.
Vec3 eddyStepOf(const EddyBatch& batch, std::size_t i, const DispersionConstants& constants,
                const DragParameters& drag, const Vec3& a, std::uint64_t seed);
} // namespace slides

HWY_BEFORE_NAMESPACE();
namespace slides::HWY_NAMESPACE {
namespace {

/// The step of the particles of one vector's lanes from `first` (`count` of them, the rest of
/// the lanes copies of the first).
struct EddyVector {
    const EddyBatch& batch;
    const DispersionConstants& constants;
    const DragParameters& drag;
    const Vec3& a;
    std::uint64_t seed;

    void operator()(std::size_t first, std::size_t count) const {
        const hn::ScalableTag<double> d;
        using V = hn::Vec<decltype(d)>;
        constexpr std::size_t lanes = maxDoubleLanes;
        // The lanes' inputs, gathered (the eddy states are records, not arrays).
        alignas(64) std::array<double, lanes> k, epsilon, radius, h, timeLeft, lengthLeft, density;
        alignas(64) std::array<double, 3 * lanes> v, u, xi, acceleration;
        const bool species = !batch.density.empty();
        for (std::size_t lane = 0; lane < hn::Lanes(d); ++lane) {
            const std::size_t i = first + (lane < count ? lane : 0);
            const EddyState& eddy = batch.eddy[i];
            k[lane] = batch.turbulentKineticEnergy[i];
            epsilon[lane] = batch.dissipationRate[i];
            radius[lane] = batch.radius[i];
            h[lane] = batch.stepLength[i];
            timeLeft[lane] = eddy.timeLeft;
            lengthLeft[lane] = eddy.lengthLeft;
            density[lane] = species ? batch.density[i] : 0.0;
            for (int c = 0; c < 3; ++c) {
                v[3 * lane + c] = batch.velocity[i][c];
                u[3 * lane + c] = batch.gas[i][c];
                xi[3 * lane + c] = eddy.standardised[c];
                acceleration[3 * lane + c] = species ? batch.acceleration[i][c] : 0.0;
            }
        }
        const V kV = hn::Load(d, k.data()), epsilonV = hn::Load(d, epsilon.data());
        const V hV = hn::Load(d, h.data()), timeV = hn::Load(d, timeLeft.data());
        const V lengthV = hn::Load(d, lengthLeft.data());
        V v0, v1, v2, u0, u1, u2, xi0, xi1, xi2;
        hn::LoadInterleaved3(d, v.data(), v0, v1, v2);
        hn::LoadInterleaved3(d, u.data(), u0, u1, u2);
        hn::LoadInterleaved3(d, xi.data(), xi0, xi1, xi2);
        // The lanes whose step may stay in its eddy: turbulent (k, ε > 0 and finite), h > 0,
        // the lifetime lasting the step and some crossing length left.
        const V infinity = hn::Set(d, std::numeric_limits<double>::infinity());
        const auto positiveFinite = [&](V x) {
            return hn::And(hn::Gt(x, hn::Zero(d)), hn::Lt(x, infinity));
        };
        auto inEddy = hn::And(hn::And(positiveFinite(kV), positiveFinite(epsilonV)),
                              hn::And(hn::Gt(hV, hn::Zero(d)), hn::Ge(timeV, hV)));
        inEddy = hn::And(inEddy, hn::Gt(lengthV, hn::Zero(d)));
        // σ = √(2k/3); slip v − U; τ(R, |v − U|); the path relative to the eddy gas over h:
        // Δ = w_∞ h + (w − w_∞) τ (1 − e^(−h/τ)), w = v − U − σξ, w_∞ = τa.
        const V sigma = hn::Sqrt(hn::Div(hn::Mul(hn::Set(d, 2.0), kV), hn::Set(d, 3.0)));
        const V s0 = hn::Sub(v0, u0), s1 = hn::Sub(v1, u1), s2 = hn::Sub(v2, u2);
        const V slip = hn::Sqrt(hn::MulAdd(s0, s0, hn::MulAdd(s1, s1, hn::Mul(s2, s2))));
        const V radiusV = hn::Load(d, radius.data());
        const V tau = species ? ResponseTime(d, drag, radiusV, slip, hn::Load(d, density.data()))
                              : ResponseTime(d, drag, radiusV, slip);
        const V reach = hn::Mul(hn::Neg(tau), hn::Expm1(d, hn::Neg(hn::Div(hV, tau))));
        const auto path = [&](V s, V xiC, V acceleration) {
            const V drift = hn::Mul(tau, acceleration);
            const V relative = hn::Sub(s, hn::Mul(sigma, xiC));
            return hn::MulAdd(hn::Sub(relative, drift), reach, hn::Mul(drift, hV));
        };
        V a0 = hn::Set(d, a.x()), a1 = hn::Set(d, a.y()), a2 = hn::Set(d, a.z());
        if (species) hn::LoadInterleaved3(d, acceleration.data(), a0, a1, a2);
        const V p0 = path(s0, xi0, a0), p1 = path(s1, xi1, a1), p2 = path(s2, xi2, a2);
        const V travelled = hn::Sqrt(hn::MulAdd(p0, p0, hn::MulAdd(p1, p1, hn::Mul(p2, p2))));
        inEddy = hn::And(inEddy, hn::Lt(travelled, lengthV));
        // ū' = (σ/h) ∫σξ dt / σ = (σ/h) ξh, as the scalar step sums it.
        const V scale = hn::Div(sigma, hV);
        alignas(64) std::array<double, 3 * lanes> fluctuation;
        hn::StoreInterleaved3(hn::Mul(scale, hn::Mul(xi0, hV)), hn::Mul(scale, hn::Mul(xi1, hV)),
                              hn::Mul(scale, hn::Mul(xi2, hV)), d, fluctuation.data());
        alignas(64) std::array<double, lanes> stays, newTime, newLength;
        hn::Store(hn::IfThenElseZero(inEddy, hn::Set(d, 1.0)), d, stays.data());
        hn::Store(hn::Sub(timeV, hV), d, newTime.data());
        hn::Store(hn::Sub(lengthV, travelled), d, newLength.data());
        for (std::size_t lane = 0; lane < count; ++lane) {
            const std::size_t i = first + lane;
            EddyState& eddy = batch.eddy[i];
            if (stays[lane] != 0) {
                eddy.timeLeft = newTime[lane];
                eddy.lengthLeft = newLength[lane];
                batch.fluctuation[i] = Vec3(fluctuation[3 * lane], fluctuation[3 * lane + 1],
                                            fluctuation[3 * lane + 2]);
            } else {
                batch.fluctuation[i] = eddyStepOf(batch, i, constants, drag, a, seed);
            }
        }
    }
};

} // namespace

void EddyInteractionBatch(const EddyBatch& batch, const DispersionConstants& constants,
                          const DragParameters& drag, const Vec3& a, std::uint64_t seed) {
    const EddyVector kernel{batch, constants, drag, a, seed};
    const std::size_t lanes = hn::Lanes(hn::ScalableTag<double>());
    forEachVector(
        batch.eddy.size(), lanes, [&](std::size_t first) { kernel(first, lanes); },
        [&](std::size_t first, std::size_t count) { kernel(first, count); });
}

} // namespace slides::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace slides {

HWY_EXPORT(EddyInteractionBatch);

Vec3 eddyStepOf(const EddyBatch& batch, std::size_t i, const DispersionConstants& constants,
                const DragParameters& drag, const Vec3& a, std::uint64_t seed) {
    const Vec3 slip = batch.velocity[i] - batch.gas[i];
    const bool species = !batch.density.empty();
    const double tau = dragResponseTime(species ? drag.withDensity(batch.density[i]) : drag,
                                        batch.radius[i], slip.norm());
    const ParticleResponse particle{slip, tau, species ? batch.acceleration[i] : a};
    return eddyInteractionStep(batch.eddy[i], constants, batch.turbulentKineticEnergy[i],
                               batch.dissipationRate[i], particle, batch.stepLength[i],
                               RandomKey{seed, batch.id[i]});
}

void eddyInteractionBatch(const EddyBatch& batch, const DispersionConstants& constants,
                          const DragParameters& drag, const Vec3& bodyAcceleration,
                          std::uint64_t seed) {
    HWY_DYNAMIC_DISPATCH(EddyInteractionBatch)(batch, constants, drag, bodyAcceleration, seed);
}

} // namespace slides
#endif
