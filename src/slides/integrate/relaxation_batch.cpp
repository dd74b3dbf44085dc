#include "slides/integrate/relaxation_batch.h"

// Compiled once per instruction set (Highway's foreach_target), dispatched at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "slides/integrate/relaxation_batch.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include "slides/core/simd_math-inl.h"

#include <hwy/highway.h>

#include <array>

HWY_BEFORE_NAMESPACE();
namespace slides::HWY_NAMESPACE {
namespace {

/// f(Re) = Cd·Re/24 of physics/drag.h, lane by lane.
template <class D, class V> HWY_INLINE V DragCorrection(D d, DragModel model, V reynolds) {
    const V one = hn::Set(d, 1.0);
    const V above1000 = hn::Mul(reynolds, hn::Set(d, 1.0 / 24.0));
    const auto highRe = hn::Gt(reynolds, hn::Set(d, 1000.0));
    switch (model) {
    case DragModel::stokes: return one;
    case DragModel::schillerNaumann: // Re < 1000: 1 + 0.15 Re^0.687, else 0.44 Re/24
        return hn::IfThenElse(hn::Ge(reynolds, hn::Set(d, 1000.0)),
                              hn::Mul(hn::Set(d, 0.44), above1000),
                              hn::MulAdd(hn::Set(d, 0.15), Pow(d, reynolds, 0.687), one));
    case DragModel::haiderLevenspiel: { // Eq. 3.17: Re 0.4251/(24 (1 + 6880.95/Re))
        const V wake = hn::Div(hn::Mul(hn::Mul(reynolds, reynolds), hn::Set(d, 0.4251 / 24.0)),
                               hn::Add(reynolds, hn::Set(d, 6880.95)));
        return hn::Add(hn::MulAdd(hn::Set(d, 0.1806), Pow(d, reynolds, 0.6459), one), wake);
    }
    case DragModel::putnam: // Re ≤ 1000: 1 + Re^(2/3)/6, else 0.424 Re/24
        return hn::IfThenElse(highRe, hn::Mul(hn::Set(d, 0.424), above1000),
                              hn::MulAdd(Pow(d, reynolds, 2.0 / 3.0), hn::Set(d, 1.0 / 6.0), one));
    }
    return one;
}

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
        // Re = 2 R |u − w| / ν; τ = τ_St / f(Re), τ_St = 2 ρp R² / (9 ρf ν).
        const V reynolds =
            hn::Mul(hn::Mul(hn::Set(d, 2.0 / drag.kinematicViscosity), radius), slip);
        const double stokes =
            2.0 * drag.particleDensity / (9.0 * drag.fluidDensity * drag.kinematicViscosity);
        const V tau = hn::Div(hn::Mul(hn::Set(d, stokes), hn::Mul(radius, radius)),
                              DragCorrection(d, drag.model, reynolds));
        // w = u + τa;  1 − e^(−h/τ);  x += w h + (v − w) τ (1 − e^(−h/τ));  v = w + (v − w)
        // e^(−h/τ).
        const V decayed = hn::Neg(hn::Expm1(d, hn::Neg(hn::Div(h, tau))));
        const V kept = hn::Sub(hn::Set(d, 1.0), decayed);
        const V reach = hn::Mul(tau, decayed);
        hn::LoadInterleaved3(d, b.startPosition[first].data(), x0, x1, x2);
        hn::LoadInterleaved3(d, b.startVelocity[first].data(), v0, v1, v2);
        const auto relax = [&](V& x, V& v, V u, double acceleration) {
            const V terminal = hn::MulAdd(tau, hn::Set(d, acceleration), u);
            const V excess = hn::Sub(v, terminal);
            x = hn::Add(x, hn::MulAdd(terminal, h, hn::Mul(excess, reach)));
            v = hn::MulAdd(excess, kept, terminal);
        };
        relax(x0, v0, u0, a.x());
        relax(x1, v1, u1, a.y());
        relax(x2, v2, u2, a.z());
        hn::StoreInterleaved3(x0, x1, x2, d, b.position[first].data());
        hn::StoreInterleaved3(v0, v1, v2, d, b.velocity[first].data());
    }

    /// The last `count` particles from `first`, padded to a whole vector with copies of the first.
    void pad(std::size_t first, std::size_t count) const {
        std::array<Vec3, maxDoubleLanes> x, v, u, w;
        std::array<double, maxDoubleLanes> radius, stepLength;
        for (std::size_t k = 0; k < maxDoubleLanes; ++k) {
            const std::size_t i = first + (k < count ? k : 0);
            x[k] = batch.startPosition[i];
            v[k] = batch.startVelocity[i];
            u[k] = batch.gas[i];
            w[k] = batch.slipOrigin[i];
            radius[k] = batch.radius[i];
            stepLength[k] = batch.stepLength[i];
        }
        run(0, {x, v, x, v, u, w, radius, stepLength});
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
