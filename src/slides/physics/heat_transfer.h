// Convective heating of a particle: lumped temperature θ (Biot ≪ 1, Eq. 2.116–2.117) driven by
// the gas temperature θf through a Nusselt correlation. Reference: Section 3.8, Eq. 3.25–3.28;
// Ranz & Marshall (1952, Chem. Eng. Prog. 48:141); Acrivos & Taylor (1962, Phys. Fluids
// 5:387); Crowe, Schwarzkopf, Sommerfeld & Tsuji (2012, Multiphase Flows with Droplets and
// Particles, §4.3) for the heat flux on the particle surface.
//
//     physics { heatTransfer { model ranzMarshall; } }   // none | ranzMarshall | acrivosTaylor
//                                                        // | michaelidesFeng
//     fluid { thermalConductivity 0.0257; specificHeat 1005; }
//     particles { specificHeat 460; injectionTemperature 293.15; }
//
// Nu = h d/K_f on the diameter d = 2R, Re = d |u − v|/ν, Pr = ρf c_f ν / K_f:
//   ranzMarshall    Nu = 2 + 0.6 Re^(1/2) Pr^(1/3)                                   (Eq. 3.27)
//   acrivosTaylor   Nu = 2 + Pe/2 + Pe² ln(Pe)/4 + 0.03404 Pe² + Pe³ ln(Pe)/16, Pe = Re Pr
//                   (Eq. 3.28: Stokes flow, a series valid for Pe ≲ 1; its first two terms are
//                   the classical Nu = 2 (1 + Pe/4))
//   michaelidesFeng Nu = 2 with the fluid's heat capacity and the history of Eq. 3.29
//                   (physics/michaelides_feng.h: an unsteady model, not a correlation)
// The heat flux over the whole surface 4πR² is Q = 4πR² h (θf − θ) = 2π Nu K_f R (θf − θ)
// (Crowe et al.; the reference's Eq. 3.25–3.26 print πR² and ½π Nu K_f R, a quarter of it).
// With m c_p dθ/dt = Q, θ relaxes to θf with the thermal response time
//   τ_θ = m c_p / (2π Nu K_f R) = 2 ρp c_p R² / (3 Nu K_f),
// integrated exactly for θf and τ_θ frozen over the step: θ(h) = θf + (θ − θf) e^(−h/τ_θ),
// stable and exact for any h/τ_θ.
// Collisions do not exist yet: the dissipated contact energy of Eq. 2.117 (ΔH/(m c_p) added
// to θ after each collision) belongs in the collision step when it comes.
//
// How to add a correlation: an enumerator, its name in heatTransferModelNames() and its case
// in nusseltNumber(); tests/verification/test_heat_transfer.cpp checks Nu → 2 as Re → 0.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

namespace slides {

enum class HeatTransferModel { none, ranzMarshall, acrivosTaylor, michaelidesFeng };

struct HeatTransferModelName {
    HeatTransferModel value;
    std::string_view name;
};

/// The name table of the heat-transfer family, as written in the dictionary.
constexpr std::array<HeatTransferModelName, 4> heatTransferModelNames() {
    return {{{HeatTransferModel::none, "none"},
             {HeatTransferModel::ranzMarshall, "ranzMarshall"},
             {HeatTransferModel::acrivosTaylor, "acrivosTaylor"},
             {HeatTransferModel::michaelidesFeng, "michaelidesFeng"}}};
}

/// Pr = ρf c_f ν / K_f of the gas.
inline double prandtlNumber(double density, double kinematicViscosity, double specificHeat,
                            double thermalConductivity) {
    return density * specificHeat * kinematicViscosity / thermalConductivity;
}

/// Nusselt number on the diameter for particle Reynolds number Re (on the diameter) and Pr;
/// 2 (pure conduction) for model none and as Re → 0.
inline double nusseltNumber(HeatTransferModel model, double reynolds, double prandtl) {
    switch (model) {
    case HeatTransferModel::none: return 2.0;
    case HeatTransferModel::michaelidesFeng: return 2.0; // Eq. 3.29's conduction term
    case HeatTransferModel::ranzMarshall:                // Eq. 3.27
        return 2.0 + 0.6 * std::sqrt(reynolds) * std::cbrt(prandtl);
    case HeatTransferModel::acrivosTaylor: { // Eq. 3.28
        const double peclet = reynolds * prandtl;
        if (!(peclet > 0)) return 2.0; // Pe² ln Pe → 0
        const double logPeclet = std::log(peclet);
        const double peclet2 = peclet * peclet;
        return 2.0 + 0.5 * peclet + 0.25 * peclet2 * logPeclet + 0.03404 * peclet2 +
               0.0625 * peclet2 * peclet * logPeclet;
    }
    }
    return 2.0;
}

/// τ_θ = 2 ρp c_p R² / (3 Nu K_f) [s]: dθ/dt = (θf − θ)/τ_θ.
inline double thermalResponseTime(double particleDensity, double particleSpecificHeat,
                                  double particleRadius, double nusselt,
                                  double thermalConductivity) {
    return 2.0 * particleDensity * particleSpecificHeat * particleRadius * particleRadius /
           (3.0 * nusselt * thermalConductivity);
}

/// θ after h with θf and τ_θ frozen: θf + (θ − θf) e^(−h/τ_θ) (exact, stable for any h).
inline double relaxTemperature(double temperature, double gasTemperature, double responseTime,
                               double h) {
    return gasTemperature + (temperature - gasTemperature) * std::exp(-h / responseTime);
}

/// θ at fraction f of a step over which it relaxed from θ0 to θ1 toward θf: the exponential
/// through both, θf + (θ0 − θf) ((θ1 − θf)/(θ0 − θf))^f (a surface touched within the step).
inline double temperatureWithinStep(double start, double end, double gasTemperature,
                                    double fraction) {
    if (start == gasTemperature) return start;
    const double remaining =
        std::clamp((end - gasTemperature) / (start - gasTemperature), 0.0, 1.0);
    return gasTemperature + (start - gasTemperature) * std::pow(remaining, fraction);
}

} // namespace slides
