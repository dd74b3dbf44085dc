// Turbulent dispersion: the gas velocity seen by a particle is U + u', with u' sampled from the
// turbulence (k, ε) of the carrier. Reference: Section 3.9, Eq. 3.31 of the reference; Gosman &
// Ioannides (1983, J. Energy 7:482) for the eddy-interaction model; Graham & James (1996, Int.
// J. Multiphase Flow 22:157) for its exponentially distributed eddy lifetimes; Pope (2000,
// Turbulent Flows, §12.3) and Gillespie (1996, Phys. Rev. E 54:2084) for the Langevin model and
// its exact update.
//
//     physics { dispersion { model eddyInteraction; Cmu 0.09; turbulentSchmidtNumber 0.7; } }
//     // model: none | eddyInteraction | langevin
//
// Scales (k-ε, C_μ = Cmu, Sc_t = turbulentSchmidtNumber):
//   rms fluctuation per component   σ = √(2k/3)   (u' carries the whole k: ⟨|u'|²⟩ = 2k)
//   Lagrangian integral time         T_L = (3 C_μ / (2 Sc_t)) k/ε
//   eddy length (Gosman–Ioannides)   l_e = C_μ^(3/4) k^(3/2)/ε
// T_L is chosen so that the long-time tracer diffusivity σ² T_L (Taylor 1921) equals the k-ε
// eddy diffusivity ν_t/Sc_t = C_μ k²/(ε Sc_t); the defaults give T_L = 0.193 k/ε.
//
// eddyInteraction: u' = σ ξ, ξ three independent standard normal deviates, held while the
//   particle stays in the eddy. The eddy ends when its lifetime, drawn from an exponential
//   distribution of mean T_L (so u' has the autocorrelation e^(−t/T_L) along a tracer path),
//   runs out, or when the particle's path relative to the eddy gas reaches l_e (crossing), which
//   comes first; then a new eddy is drawn. The relative path follows the drag relaxation of the
//   particle (response time τ, body acceleration a): heavy or settling particles cross eddies,
//   tracers never do.
// langevin: the continuous random walk du' = −u'/T_L dt + σ √(2/T_L) dW (Ornstein–Uhlenbeck),
//   no eddy boundaries; advanced exactly over any step. It uses the fluid's T_L for every
//   particle (no crossing-trajectory reduction of the time scale a drifting particle sees).
//
// Over a step h the particle is advanced with U + ū', ū' the time average of u' over the step:
// the eddy sequence is walked in sub-steps (as many eddies as end inside h), and the Langevin
// update draws u'(t + h) and ∫u' dt jointly and exactly. So dispersion never switches off when
// h exceeds the eddy lifetime, and a tracer's displacement has the exact distribution for any h.
// More than 50 T_L of one step (a step far longer than the eddies) are drawn in one piece: a
// Gaussian of the exact variance of ∫u' dt, without crossing.
// u' is stored in units of the local σ, so a particle that moves into weaker turbulence sees a
// weaker fluctuation; where k or ε is 0 the gas is laminar there (u' = 0, the eddy ends); a
// non-finite k or ε gives a non-finite u', which the stepper stops on.
//
// How to add a model: an enumerator, its name in dispersionModelNames(), its function here and
// its case in seenGasFluctuation (physics/dispersion.cpp).
#pragma once

#include "slides/core/eddy_state.h"
#include "slides/core/vector.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <string_view>

namespace slides {

enum class DispersionModel { none, eddyInteraction, langevin };

struct DispersionModelName {
    DispersionModel value;
    std::string_view name;
};

/// The name table of the dispersion family, as written in the dictionary.
constexpr std::array<DispersionModelName, 3> dispersionModelNames() {
    return {{{DispersionModel::none, "none"},
             {DispersionModel::eddyInteraction, "eddyInteraction"},
             {DispersionModel::langevin, "langevin"}}};
}

struct DispersionConstants {
    double Cmu = 0.09;                   ///< k-ε C_μ (Launder & Spalding 1974)
    double turbulentSchmidtNumber = 0.7; ///< Sc_t = ν_t / (particle diffusivity)
};

/// σ = √(2k/3): rms of each component of u' [m/s].
inline double fluctuationRms(double k) { return std::sqrt(2.0 * k / 3.0); }

/// T_L = (3 C_μ/(2 Sc_t)) k/ε [s]: σ² T_L = C_μ k²/(ε Sc_t) = ν_t/Sc_t.
inline double lagrangianTimeScale(const DispersionConstants& constants, double k, double epsilon) {
    return 1.5 * constants.Cmu / constants.turbulentSchmidtNumber * k / epsilon;
}

/// l_e = C_μ^(3/4) k^(3/2)/ε [m] (Gosman & Ioannides 1983).
inline double eddyLengthScale(const DispersionConstants& constants, double k, double epsilon) {
    return std::pow(constants.Cmu, 0.75) * k * std::sqrt(k) / epsilon;
}

/// The particle's motion relative to the mean gas at the step start, for eddy crossing:
/// dv/dt = (U + u' − v)/τ + a.
struct ParticleResponse {
    Vec3 slip = Vec3::Zero();             ///< v − U [m/s]
    double responseTime = 0;              ///< τ [s]
    Vec3 bodyAcceleration = Vec3::Zero(); ///< a [m/s²]
};

/// Where a particle's random numbers come from: stream (seed, id, eddy, state.count).
struct RandomKey {
    std::uint64_t seed = 0;
    std::uint64_t particleId = 0;
};

/// Starts a new eddy: ξ ~ N(0, I), lifetime ~ Exp(mean T_L), crossing length l_e.
void drawEddy(EddyState& state, double lagrangianTime, double eddyLength, RandomKey key);

/// eddyInteraction: walks the eddies over h and returns the time-averaged u' over the step.
Vec3 eddyInteractionStep(EddyState& state, const DispersionConstants& constants, double k,
                         double epsilon, const ParticleResponse& particle, double h, RandomKey key);

/// langevin: advances u' exactly over h and returns its time average over the step.
Vec3 langevinStep(EddyState& state, const DispersionConstants& constants, double k, double epsilon,
                  double h, RandomKey key);

} // namespace slides
