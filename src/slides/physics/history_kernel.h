// History-force kernels: Basset's 1/√t and the finite-Reynolds kernels of Mei & Adrian and Kim.
//
// Reference: Eq. 3.2–3.15 of the reference. The history force is
//   F_H = 6πμR ∫ K(t − τ, τ) d(u − v)/dτ dτ   (Eq. 3.4, 3.8),
// with Basset's kernel K_B = R/√(πν(t − τ)) (Eq. 3.2/3.3: 6R²√(πμρf)/√(t − τ)). Mei & Adrian
// (1992, J. Fluid Mech. 237:323) and Kim, Elghobashi & Sirignano (1998, J. Fluid Mech. 367:221)
// keep K_B at short lags and let it decay as (t − τ)^(−2) at long ones (Eq. 3.5–3.7, 3.9–3.14;
// the extracted Eq. 3.5 lost the outer exponent −2 of the original paper). Per unit effective
// mass m_e = m_p + C_A m_f (physics/unsteady.h), the Basset term is
//   a_H = r_H d/dt ∫_0^t (u − v)(τ)/√(t − τ) dτ,  r_H = 9 ρf √ν / (2 √π (ρp + C_A ρf) R),
// which already contains Maxey's initial-slip term (u − v)(0)/√t.
//
//     physics { history { model basset; accuracy 1e-3; } }   // none | basset | meiAdrian | kim
#pragma once

#include "slides/physics/particle_reynolds.h"

#include <cmath>
#include <numbers>

namespace slides {

/// Basset kernel K_B(lag) = R/√(πν·lag) of Eq. 3.2 in the form 6πμR ∫ K_B d(u − v)/dτ dτ.
inline double bassetKernel(double lag, double particleRadius, double kinematicViscosity) {
    return particleRadius / std::sqrt(std::numbers::pi * kinematicViscosity * lag);
}

/// r_H [1/√s]: the Basset acceleration per unit effective mass is r_H d/dt ∫ (u − v)/√(t − τ) dτ.
inline double bassetHistoryRate(double particleDensity, double fluidDensity,
                                double kinematicViscosity, double particleRadius,
                                double addedMassCoefficient) {
    return 9.0 * fluidDensity * std::sqrt(kinematicViscosity) /
           (2.0 * std::sqrt(std::numbers::pi) *
            (particleDensity + addedMassCoefficient * fluidDensity) * particleRadius);
}

/// The long-lag term π|u − v|³ lag² / (2 R ν f_H³) shared by Eq. 3.5 and 3.9.
inline double historyDecayTerm(double lag, double slipSpeed, double particleRadius,
                               double kinematicViscosity, double fH) {
    return std::numbers::pi * slipSpeed * slipSpeed * slipSpeed * lag * lag /
           (2.0 * particleRadius * kinematicViscosity * fH * fH * fH);
}

/// Mei & Adrian's kernel (Eq. 3.5–3.7): {[πν lag/R²]^(1/4) + [π|u−v|³lag²/(2Rν f_H³)]^(1/2)}^(−2),
/// f_H = 0.75 + 0.105 Re(τ); slipSpeed is |u − v| at the earlier time τ.
inline double meiAdrianKernel(double lag, double slipSpeed, double particleRadius,
                              double kinematicViscosity) {
    const double reynolds = particleReynolds(slipSpeed, particleRadius, kinematicViscosity);
    const double fH = 0.75 + 0.105 * reynolds;
    const double shortLag = std::pow(
        std::numbers::pi * kinematicViscosity * lag / (particleRadius * particleRadius), 0.25);
    const double longLag =
        std::sqrt(historyDecayTerm(lag, slipSpeed, particleRadius, kinematicViscosity, fH));
    const double sum = shortLag + longLag;
    return 1.0 / (sum * sum);
}

/// Coefficients c1…c6 of Kim et al. (Eq. 3.15).
struct KimCoefficients {
    static constexpr double c1 = 2.5, c2 = 22.0, c3 = 0.07, c4 = 0.25, c5 = 0.126, c6 = 17.8;
};

/// Kim et al.'s kernel (Eq. 3.9, 3.12):
/// {[πν lag/R²]^(1/(2c1)) + G [π|u−v|³lag²/(2Rν f_H³)]^(1/c1)}^(−c1), f_H = 0.75 + c5 Re(τ).
/// G (Eq. 3.10) carries the relative acceleration of the particle at τ; G = 1 without it.
inline double kimKernel(double lag, double slipSpeed, double particleRadius,
                        double kinematicViscosity, double accelerationFactor) {
    using C = KimCoefficients;
    const double reynolds = particleReynolds(slipSpeed, particleRadius, kinematicViscosity);
    const double fH = 0.75 + C::c5 * reynolds;
    const double shortLag =
        std::pow(std::numbers::pi * kinematicViscosity * lag / (particleRadius * particleRadius),
                 1.0 / (2.0 * C::c1));
    const double longLag = std::pow(
        historyDecayTerm(lag, slipSpeed, particleRadius, kinematicViscosity, fH), 1.0 / C::c1);
    return std::pow(shortLag + accelerationFactor * longLag, -C::c1);
}

/// G1 of Eq. 3.14 for the initial-slip kernel K1 (Eq. 3.13): 1/(1 + c6 Re0^(−1/4)(ρp/ρf + ½)^(−½)).
inline double kimInitialFactor(double initialReynolds, double densityRatio) {
    using C = KimCoefficients;
    return 1.0 / (1.0 + C::c6 * std::pow(initialReynolds, -0.25) / std::sqrt(densityRatio + 0.5));
}

/// K1(t) of Eq. 3.13: Kim's kernel at lag t with the initial slip |u − v|(0) and G = G1.
inline double kimInitialKernel(double time, double initialSlipSpeed, double particleRadius,
                               double kinematicViscosity, double densityRatio) {
    const double reynolds = particleReynolds(initialSlipSpeed, particleRadius, kinematicViscosity);
    return kimKernel(time, initialSlipSpeed, particleRadius, kinematicViscosity,
                     kimInitialFactor(reynolds, densityRatio));
}

} // namespace slides
