// Regularised Coulomb friction of a sliding contact: the stick–slip jump smoothed over a slip
// speed ε, as an option of the soft-sphere tangential law in place of the Mindlin spring.
//
// Reference: Section 2.5 of the reference, Eq. 2.65–2.68 (Oden & Pires 1983; Wriggers 2006):
// f_T = μ R(v_slip) |f_N| against the slip, with
//   linear    R₁ = v/ε for |v| ≤ ε, ±1 beyond (Eq. 2.66; its middle branch prints v/(2ε),
//             which would jump at ±ε: v/ε is the continuous ramp of Fig. 2.4),
//   tanh      R₂ = tanh(v/ε) (Eq. 2.67),
//   algebraic R₃ = v/√(v² + ε²) (Eq. 2.68).
// A smaller ε comes closer to stick–slip; a contact then never sticks exactly but creeps at a
// slip speed of order ε.
//
//     collisions { friction { dynamic 0.3; regularisation tanh; slipSpeed 1e-3; } }
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

namespace slides {

enum class FrictionRegularisation { none, linear, tanh, algebraic };

struct FrictionRegularisationName {
    FrictionRegularisation value;
    std::string_view name;
};

// How to add one: an enumerator, its name here, its case in regularisedFriction.
constexpr std::array<FrictionRegularisationName, 4> frictionRegularisationNames() {
    return {{{FrictionRegularisation::none, "none"},
             {FrictionRegularisation::linear, "linear"},
             {FrictionRegularisation::tanh, "tanh"},
             {FrictionRegularisation::algebraic, "algebraic"}}};
}

/// R(v) ∈ [0, 1] for a slip speed v ≥ 0 and regularisation speed ε > 0 (Eq. 2.66–2.68); the
/// friction force is μ R |f_N| against the slip. none: 1 (the Coulomb limit itself).
inline double regularisedFriction(FrictionRegularisation regularisation, double slipSpeed,
                                  double regularisationSpeed) {
    const double ratio = slipSpeed / regularisationSpeed;
    switch (regularisation) {
    case FrictionRegularisation::none: return 1.0;
    case FrictionRegularisation::linear: return std::min(ratio, 1.0);
    case FrictionRegularisation::tanh: return std::tanh(ratio);
    case FrictionRegularisation::algebraic: return ratio / std::sqrt(ratio * ratio + 1.0);
    }
    return 1.0;
}

} // namespace slides
