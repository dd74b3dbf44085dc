// The drag response time τ = τ_St / f(Re) of physics/drag.h (dragResponseTime, Eq. 3.16–3.17
// and its kin) lane by lane, for the SIMD kernels (integrate/relaxation_batch.h,
// integrate/eddy_batch.h). The scalar dragResponseTime stays the reference:
// tests/unit/test_vector_kernels.cpp holds them within 1e-13 of each other.
//
//     physics { drag haiderLevenspiel; }   // stokes | schillerNaumann | haiderLevenspiel | putnam

// Per-target include guard (Highway's convention for headers included by foreach_target).
#if defined(SLIDES_PHYSICS_DRAG_RESPONSE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SLIDES_PHYSICS_DRAG_RESPONSE_INL_H_
#undef SLIDES_PHYSICS_DRAG_RESPONSE_INL_H_
#else
#define SLIDES_PHYSICS_DRAG_RESPONSE_INL_H_
#endif

#include "slides/core/simd_math-inl.h"
#include "slides/physics/drag.h"

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace slides::HWY_NAMESPACE {

/// f(Re) = Cd·Re/24 of physics/drag.h (dragCorrection), lane by lane.
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

/// τ(R, |u − w|) = τ_St / f(Re), Re = 2 R |u − w| / ν, τ_St = 2 ρp R² / (9 ρf ν).
template <class D, class V>
HWY_INLINE V ResponseTime(D d, const DragParameters& drag, V radius, V slip) {
    const V reynolds = hn::Mul(hn::Mul(hn::Set(d, 2.0 / drag.kinematicViscosity), radius), slip);
    const double stokes =
        2.0 * drag.particleDensity / (9.0 * drag.fluidDensity * drag.kinematicViscosity);
    return hn::Div(hn::Mul(hn::Set(d, stokes), hn::Mul(radius, radius)),
                   DragCorrection(d, drag.model, reynolds));
}

/// τ as above for particles of their own density ρp, one a lane (particle species,
/// integrate/injection_settings.h): 2 ρp / (9 ρf ν) rounded as the kernel above rounds it, so a
/// particle's τ is the same bits as in a run of its density alone.
template <class D, class V>
HWY_INLINE V ResponseTime(D d, const DragParameters& drag, V radius, V slip, V density) {
    const V reynolds = hn::Mul(hn::Mul(hn::Set(d, 2.0 / drag.kinematicViscosity), radius), slip);
    const V stokes = hn::Div(hn::Mul(hn::Set(d, 2.0), density),
                             hn::Set(d, 9.0 * drag.fluidDensity * drag.kinematicViscosity));
    return hn::Div(hn::Mul(stokes, hn::Mul(radius, radius)),
                   DragCorrection(d, drag.model, reynolds));
}

} // namespace slides::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif // per-target include guard
