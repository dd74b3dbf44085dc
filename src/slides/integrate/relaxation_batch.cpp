#include "slides/integrate/relaxation_batch.h"

// Compiled once per instruction set (Highway's foreach_target), dispatched at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "slides/integrate/relaxation_batch.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include "slides/core/simd_math-inl.h"
#include "slides/physics/drag_response-inl.h"

#include <hwy/highway.h>

#include <array>

HWY_BEFORE_NAMESPACE();
namespace slides::HWY_NAMESPACE {
namespace {

/// relaxExactly for the lanes of one vector starting at particle `first`.
struct RelaxVector {
    const RelaxationBatch& batch;
    const DragParameters& drag;
    const Vec3& a;
    double fraction;

    void operator()(std::size_t first) const { run(first, batch); }

    void run(std::size_t first, const RelaxationBatch& b) const {
        const hn::ScalableTag<double> d;
        using V = hn::Vec<decltype(d)>;
        V x0, x1, x2, v0, v1, v2, u0, u1, u2, w0, w1, w2;
        hn::LoadInterleaved3(d, b.gas[first].data(), u0, u1, u2);
        hn::LoadInterleaved3(d, b.slipOrigin[first].data(), w0, w1, w2);
        const V radius = hn::LoadU(d, &b.radius[first]);
        const V h = hn::Mul(hn::Set(d, fraction), hn::LoadU(d, &b.stepLength[first]));
        const V s0 = hn::Sub(u0, w0), s1 = hn::Sub(u1, w1), s2 = hn::Sub(u2, w2);
        const V slip = hn::Sqrt(hn::MulAdd(s0, s0, hn::MulAdd(s1, s1, hn::Mul(s2, s2))));
        const bool species = !b.density.empty();
        const V tau = species ? ResponseTime(d, drag, radius, slip, hn::LoadU(d, &b.density[first]))
                              : ResponseTime(d, drag, radius, slip);
        // w = u + τa;  1 − e^(−h/τ);  x += w h + (v − w) τ (1 − e^(−h/τ));  v = w + (v − w)
        // e^(−h/τ).
        const V decayed = hn::Neg(hn::Expm1(d, hn::Neg(hn::Div(h, tau))));
        const V kept = hn::Sub(hn::Set(d, 1.0), decayed);
        const V reach = hn::Mul(tau, decayed);
        hn::LoadInterleaved3(d, b.startPosition[first].data(), x0, x1, x2);
        hn::LoadInterleaved3(d, b.startVelocity[first].data(), v0, v1, v2);
        const auto relax = [&](V& x, V& v, V u, V acceleration) {
            const V terminal = hn::MulAdd(tau, acceleration, u);
            const V excess = hn::Sub(v, terminal);
            x = hn::Add(x, hn::MulAdd(terminal, h, hn::Mul(excess, reach)));
            v = hn::MulAdd(excess, kept, terminal);
        };
        V a0 = hn::Set(d, a.x()), a1 = hn::Set(d, a.y()), a2 = hn::Set(d, a.z());
        if (species) hn::LoadInterleaved3(d, b.acceleration[first].data(), a0, a1, a2);
        relax(x0, v0, u0, a0);
        relax(x1, v1, u1, a1);
        relax(x2, v2, u2, a2);
        hn::StoreInterleaved3(x0, x1, x2, d, b.position[first].data());
        hn::StoreInterleaved3(v0, v1, v2, d, b.velocity[first].data());
    }

    /// The last `count` particles from `first`, padded to a whole vector with copies of the first.
    void pad(std::size_t first, std::size_t count) const {
        std::array<Vec3, maxDoubleLanes> x, v, u, w, acceleration;
        std::array<double, maxDoubleLanes> radius, stepLength, density;
        const bool species = !batch.density.empty();
        for (std::size_t k = 0; k < maxDoubleLanes; ++k) {
            const std::size_t i = first + (k < count ? k : 0);
            x[k] = batch.startPosition[i];
            v[k] = batch.startVelocity[i];
            u[k] = batch.gas[i];
            w[k] = batch.slipOrigin[i];
            radius[k] = batch.radius[i];
            stepLength[k] = batch.stepLength[i];
            density[k] = species ? batch.density[i] : 0.0;
            acceleration[k] = species ? batch.acceleration[i] : Vec3::Zero();
        }
        RelaxationBatch padded{x, v, x, v, u, w, radius, stepLength};
        if (species) {
            padded.density = density;
            padded.acceleration = acceleration;
        }
        run(0, padded);
        for (std::size_t k = 0; k < count; ++k) {
            batch.position[first + k] = x[k];
            batch.velocity[first + k] = v[k];
        }
    }
};

} // namespace

void RelaxBatchExactly(const RelaxationBatch& batch, const DragParameters& drag, const Vec3& a,
                       double fraction) {
    const RelaxVector kernel{batch, drag, a, fraction};
    forEachVector(
        batch.position.size(), hn::Lanes(hn::ScalableTag<double>()),
        [&](std::size_t first) { kernel(first); },
        [&](std::size_t first, std::size_t count) { kernel.pad(first, count); });
}

} // namespace slides::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace slides {

HWY_EXPORT(RelaxBatchExactly);

void relaxBatchExactly(const RelaxationBatch& batch, const DragParameters& drag,
                       const Vec3& bodyAcceleration, double fraction) {
    HWY_DYNAMIC_DISPATCH(RelaxBatchExactly)(batch, drag, bodyAcceleration, fraction);
}

} // namespace slides
#endif
