// Normal force–displacement laws of a soft-sphere contact beside Hertz's: the linear
// spring–dashpot, Brilliantov's viscoelastic Hertz and Walton–Braun's hysteretic spring, with
// the closed forms of their impacts.
//
// Reference: Section 2.2 of the reference, Eq. 2.6–2.10.
//   linearSpringDashpot (Eq. 2.6, 2.7): F = k δ + γ dδ/dt, γ = 2ζ√(k m*); a head-on impact
//     restitutes e = exp(−πζ/√(1 − ζ²)) and lasts t_c = π/ω_d, ω_d = √(k/m*) √(1 − ζ²)
//     (Pöschel & Schwager 2005, §3.1). The force is not clamped at 0: the closed form is the
//     damped oscillator's, whose last instants pull slightly.
//   viscoelasticHertz (Eq. 2.8; Brilliantov, Spahn, Hertzsch & Pöschel 1996, Phys. Rev. E
//     53:5382): F = K_n (δ^{3/2} + 3/2 A √δ dδ/dt), K_n = 4/3 E*√R*, clamped at 0 (Schwager &
//     Pöschel 2008, Phys. Rev. E 78:051304). The printed Eq. 2.8 folds the 3/2 into A; A here
//     is Brilliantov's dissipative time, so that e = 1 − C₁ A α^{2/5} v^{1/5} + … with
//     α = 3/2 K_n/m*, C₁ = 1.15344 (Schwager & Pöschel 1998, Phys. Rev. E 57:650).
//   waltonBraun (Eq. 2.9, 2.10; Walton & Braun 1986, J. Rheol. 30:949): loading F = k_L δ,
//     unloading F = k_U (δ − δ₀) with δ₀ = δ_max (1 − k_L/k_U), never negative; reloading
//     follows the unloading line up to the loading one. k_U = k_L/e² restitutes e = √(k_L/k_U)
//     at every speed; the force acts for t_c = π/2 (√(m*/k_L) + √(m*/k_U)).
//
//     collisions { softSphereCoeffs { contactLaw linearSpringDashpot; normalStiffness 1e5; } }
//     collisions { softSphereCoeffs { contactLaw viscoelasticHertz; dissipativeTime 1e-7; } }
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string_view>

namespace slides {

enum class NormalContactLaw { hertz, linearSpringDashpot, viscoelasticHertz, waltonBraun };

struct NormalContactLawName {
    NormalContactLaw value;
    std::string_view name;
};

// How to add a law: an enumerator, its name here, its cases in physics/soft_contact.cpp's
// elasticNormalForce, dampingCoefficient and dampingExponent (or, without a dashpot, its force in
// normalContactForce), and its contact duration in softContactDuration.
constexpr std::array<NormalContactLawName, 4> normalContactLawNames() {
    return {{{NormalContactLaw::hertz, "hertz"},
             {NormalContactLaw::linearSpringDashpot, "linearSpringDashpot"},
             {NormalContactLaw::viscoelasticHertz, "viscoelasticHertz"},
             {NormalContactLaw::waltonBraun, "waltonBraun"}}};
}

/// Damping ratio ζ = −ln e / √(π² + ln²e) of a linear spring–dashpot restituting e (Eq. 2.7).
inline double linearDampingRatio(double restitution) {
    const double logE = std::log(restitution);
    return -logE / std::sqrt(std::numbers::pi * std::numbers::pi + logE * logE);
}

/// Restitution e = exp(−πζ/√(1 − ζ²)) of a linear spring–dashpot of damping ratio ζ < 1 (Eq. 2.7).
inline double linearRestitution(double dampingRatio) {
    return std::exp(-std::numbers::pi * dampingRatio / std::sqrt(1 - dampingRatio * dampingRatio));
}

/// Duration π/ω_d [s] of a linear spring–dashpot impact, ω_d = √(k/m*) √(1 − ζ²).
inline double linearContactDuration(double stiffness, double mass, double dampingRatio) {
    return std::numbers::pi / (std::sqrt(stiffness / mass * (1 - dampingRatio * dampingRatio)));
}

/// Walton–Braun unloading stiffness k_U = k_L/e² that restitutes e (Eq. 2.10).
inline double waltonBraunUnloadingStiffness(double loadingStiffness, double restitution) {
    return loadingStiffness / (restitution * restitution);
}

/// Time the Walton–Braun force acts in an impact [s]: a quarter period on each spring.
inline double waltonBraunContactDuration(double loadingStiffness, double mass, double restitution) {
    const double unloading = waltonBraunUnloadingStiffness(loadingStiffness, restitution);
    return 0.5 * std::numbers::pi *
           (std::sqrt(mass / loadingStiffness) + std::sqrt(mass / unloading));
}

/// Walton–Braun force [N] at overlap δ after the largest overlap δ_max ≥ δ (Eq. 2.9, 2.10).
inline double waltonBraunForce(double loadingStiffness, double restitution, double overlap,
                               double largestOverlap) {
    const double unloading = waltonBraunUnloadingStiffness(loadingStiffness, restitution);
    const double plasticOverlap = largestOverlap * (1 - loadingStiffness / unloading); // δ₀
    return std::max(0.0,
                    std::min(loadingStiffness * overlap, unloading * (overlap - plasticOverlap)));
}

} // namespace slides
