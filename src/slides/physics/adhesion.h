// Adhesion on impact: the pull-off force of a contact and the deposition criterion of
// Section 5.3.2 (Eq. 5.7–5.9).
//
// Reference: Eq. 2.72–2.75 and 5.7–5.9 of the reference.
//   interfaceEnergy: F_adh = 2π R* W₁₂ (Derjaguin, Eq. 2.72, with U(ε₀) = −W₁₂), which is
//     Eq. 2.73's 4πγR for two equal surfaces; W₁₂ = 2√(γ₁γ₂) (physics/contact_pair.h).
//     (Eq. 5.7 prints 4πγ₁₂R with γ₁₂ ≈ 2√(γ₁γ₂): twice this force for unequal surfaces and
//     four times Eq. 2.73's for equal ones; the adhesion factor absorbs such constants.)
//   hamaker: F_adh = A R* / (6 ε₀²), the sphere–plane van der Waals force at contact
//     separation ε₀ (Eq. 2.72 with Eq. 2.75's U = −A/(12π ε₀²)).
//   jkr: F_adh = 3/2 π W₁₂ R* (Eq. 2.84), dmt: 2π W₁₂ R* (Eq. 2.91), taborMap: JKR's where
//     Tabor's μ_T of the pair (Eq. 2.92, with ε₀) is at least 1, else DMT's
//     (physics/adhesive_contact.h).
// All are multiplied by the adhesion factor α_adh (Table 5.2 assumes 5000).
// A particle sticks when its normal rebound speed of Eq. 5.8 is not positive, which for an
// inelastic impact (δt − δt₁ = 1.2 e δt₁, Eq. 2.64) is (Eq. 5.9)
//   v₀ < 0.2 F_adh δt₁ / m*,
// with δt₁ the compression time (physics/restitution.h).
//
//     deposition { adhesion interfaceEnergy; adhesionFactor 5000; }
//     deposition { adhesion hamaker; hamakerConstant 1e-19; contactSeparation 4e-10; }
//     deposition { adhesion taborMap; adhesionFactor 1; contactSeparation 4e-10; }
#pragma once

#include "slides/physics/adhesive_contact.h"
#include "slides/physics/contact_pair.h"
#include "slides/physics/restitution.h"

#include <array>
#include <cmath>
#include <string_view>

namespace slides {

enum class AdhesionModel { interfaceEnergy, hamaker, jkr, dmt, taborMap };

struct AdhesionModelName {
    AdhesionModel value;
    std::string_view name;
};

// How to add a model: an enumerator, its name here, its case in adhesionForce.
constexpr std::array<AdhesionModelName, 5> adhesionModelNames() {
    return {{{AdhesionModel::interfaceEnergy, "interfaceEnergy"},
             {AdhesionModel::hamaker, "hamaker"},
             {AdhesionModel::jkr, "jkr"},
             {AdhesionModel::dmt, "dmt"},
             {AdhesionModel::taborMap, "taborMap"}}};
}

struct AdhesionSettings {
    AdhesionModel model = AdhesionModel::interfaceEnergy;
    double factor = 1;                ///< α_adh multiplying the force (Table 5.2: 5000)
    double hamakerConstant = 0;       ///< A [J]
    double contactSeparation = 4e-10; ///< ε₀ [m] (Israelachvili: 0.165–0.4 nm)
};

/// Pull-off force of the pair at contact [N] (Eq. 2.72–2.75, 5.7).
inline double adhesionForce(const AdhesionSettings& settings, const ContactPair& pair) {
    switch (settings.model) {
    case AdhesionModel::interfaceEnergy:
        return settings.factor * 2 * M_PI * pair.radius * pair.workOfAdhesion;
    case AdhesionModel::hamaker:
        return settings.factor * settings.hamakerConstant * pair.radius /
               (6 * settings.contactSeparation * settings.contactSeparation);
    case AdhesionModel::jkr:
        return -settings.factor * jkrPullOffForce(pair.radius, pair.workOfAdhesion);
    case AdhesionModel::dmt:
        return -settings.factor * dmtPullOffForce(pair.radius, pair.workOfAdhesion);
    case AdhesionModel::taborMap: {
        const bool jkr = taborSelectsJkr(taborParameter(
            pair.radius, pair.workOfAdhesion, pair.youngsModulus, settings.contactSeparation));
        return -settings.factor * (jkr ? jkrPullOffForce(pair.radius, pair.workOfAdhesion)
                                       : dmtPullOffForce(pair.radius, pair.workOfAdhesion));
    }
    }
    return 0;
}

/// Largest normal impact speed at which the pair sticks, 0.2 F_adh δt₁ / m* (Eq. 5.9) [m/s].
/// δt₁ is that of the impact itself: Eq. 2.64 above v_Y, half the Hertz duration below.
inline double stickingSpeedLimit(const AdhesionSettings& adhesion,
                                 const RestitutionSettings& restitution, const ContactPair& pair,
                                 double normalSpeed) {
    return 0.2 * adhesionForce(adhesion, pair) * compressionTime(restitution, pair, normalSpeed) /
           pair.mass;
}

/// Whether an impact at normalSpeed sticks (Eq. 5.9).
inline bool sticks(const AdhesionSettings& adhesion, const RestitutionSettings& restitution,
                   const ContactPair& pair, double normalSpeed) {
    return normalSpeed < stickingSpeedLimit(adhesion, restitution, pair, normalSpeed);
}

} // namespace slides
