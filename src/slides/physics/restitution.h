// Restitution of an impact: a constant coefficient, or the velocity-dependent elastic–plastic
// model of Section 2.4 (Eq. 2.59–2.64), and the compression time it implies.
//
// Reference: Eq. 2.59–2.64 of the reference, after Johnson, Contact Mechanics (1985), §11.4
// (Hertz impact; rigid–perfectly plastic impact with mean pressure p_m = αY):
//   v_Y from ½ m v_Y² = 5.1 α⁵ R³ Y⁵ / E*⁴                         (2.63, yield onset, α_Y = α)
//   e = 1.88 α^{5/8} √(Y/E*) (½ m v² / (Y R³))^{−1/8}  for v > v_Y, else 1   (2.62)
//   δt₁ = √(π m / (8 R α Y)) for v > v_Y (compression), δt − δt₁ = 1.2 e δt₁  (2.64)
//   δt = 2.94 δ_max / v = 2.87 (m² / (R E*² v))^{1/5} for an elastic (Hertz) impact,
//   δt₁ = δt/2 (2.59; physics/soft_contact.h)
// m, R and E* are the pair's effective mass, radius and modulus (physics/contact_pair.h).
//
//     collisions { restitution { model velocityDependent; yieldPressureFactor 3; } }
//     collisions { restitution { model constant; coefficient 0.9; } }
#pragma once

#include "slides/physics/contact_pair.h"
#include "slides/physics/soft_contact.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

namespace slides {

enum class RestitutionModel { constant, velocityDependent };

struct RestitutionModelName {
    RestitutionModel value;
    std::string_view name;
};

// How to add a model: an enumerator, its name here, its case in restitutionCoefficient.
constexpr std::array<RestitutionModelName, 2> restitutionModelNames() {
    return {{{RestitutionModel::constant, "constant"},
             {RestitutionModel::velocityDependent, "velocityDependent"}}};
}

struct RestitutionSettings {
    RestitutionModel model = RestitutionModel::velocityDependent;
    double coefficient = 0.9;       ///< e of the constant model
    double yieldPressureFactor = 3; ///< α of p_m = αY (3 for metals, ≈ 1 for foams; Eq. 2.60)
};

/// Impact speed below which the contact stays elastic, v_Y of Eq. 2.63 [m/s].
inline double yieldVelocity(const ContactPair& pair, double alpha) {
    const double Y = pair.yieldStress;
    const double energy = 5.1 * std::pow(alpha, 5) * std::pow(pair.radius, 3) * std::pow(Y, 5) /
                          std::pow(pair.youngsModulus, 4);
    return std::sqrt(2 * energy / pair.mass);
}

/// Restitution coefficient for a normal impact speed (> 0) [m/s] (Eq. 2.62; 1 below v_Y).
inline double restitutionCoefficient(const RestitutionSettings& settings, const ContactPair& pair,
                                     double normalSpeed) {
    if (settings.model == RestitutionModel::constant) return settings.coefficient;
    const double alpha = settings.yieldPressureFactor;
    const double Y = pair.yieldStress;
    if (!(Y > 0) || normalSpeed <= yieldVelocity(pair, alpha)) return 1.0;
    const double energyRatio =
        0.5 * pair.mass * normalSpeed * normalSpeed / (Y * std::pow(pair.radius, 3));
    return std::min(1.0, 1.88 * std::pow(alpha, 0.625) * std::sqrt(Y / pair.youngsModulus) *
                             std::pow(energyRatio, -0.125));
}

/// Compression time δt₁ of an impact (Eq. 2.64 above v_Y; half the Hertz duration, Eq. 2.59,
/// below) [s].
inline double compressionTime(const RestitutionSettings& settings, const ContactPair& pair,
                              double normalSpeed) {
    const double alpha = settings.yieldPressureFactor;
    if (pair.yieldStress > 0 && normalSpeed > yieldVelocity(pair, alpha))
        return std::sqrt(M_PI * pair.mass / (8 * pair.radius * alpha * pair.yieldStress));
    return 0.5 * hertzContactDuration(pair, normalSpeed);
}

} // namespace slides
