// Lift on a sphere: Saffman–Mei shear lift and Rubinow–Keller (Magnus) spin lift.
//
// Reference: Sec. 3.4 of the reference (Saffman and Magnus lift added to Eq. 3.3); Saffman
// (1965, J. Fluid Mech. 22:385) with Mei's finite-Reynolds correction (1992, Int. J. Multiphase
// Flow 18:145), in the form of OpenFOAM's SaffmanMeiLiftForce: F = V_p ρf C_l (u − v) × (∇×U),
// C_l = 3/(2π√Re_ω) C_ld, Re_ω = |∇×U| d²/ν, β = Re_ω/(2 Re), α = 0.3314 √β,
// C_ld = 6.46 ((1 − α) e^{−0.1 Re} + α) for Re < 40, 6.46 · 0.0524 √(β Re) above.
// Magnus: F = π R³ ρf Ω × (v − u) with Ω = ω − ½∇×U (Rubinow & Keller 1961).
//
//     physics { lift saffmanMei; }   // none | saffmanMei | magnus | saffmanMeiMagnus
#pragma once

#include "slides/core/vector.h"
#include "slides/physics/particle_reynolds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string_view>

namespace slides {

enum class LiftModel { none, saffmanMei, magnus, saffmanMeiMagnus };

struct LiftModelName {
    LiftModel value;
    std::string_view name;
};

/// The name table of the lift family. How to add one: an enumerator, its name, its branch in
/// liftAcceleration().
constexpr std::array<LiftModelName, 4> liftModelNames() {
    return {{{LiftModel::none, "none"},
             {LiftModel::saffmanMei, "saffmanMei"},
             {LiftModel::magnus, "magnus"},
             {LiftModel::saffmanMeiMagnus, "saffmanMeiMagnus"}}};
}

inline bool usesShearLift(LiftModel model) {
    return model == LiftModel::saffmanMei || model == LiftModel::saffmanMeiMagnus;
}
inline bool usesSpinLift(LiftModel model) {
    return model == LiftModel::magnus || model == LiftModel::saffmanMeiMagnus;
}

/// Saffman–Mei lift coefficient C_l (Mei 1992) for particle and shear Reynolds numbers.
inline double saffmanMeiCoefficient(double reynolds, double shearReynolds) {
    if (shearReynolds <= 0) return 0;
    const double beta = 0.5 * shearReynolds / std::max(reynolds, 1e-300);
    const double cld = reynolds < 40
                           ? 6.46 * ((1 - 0.3314 * std::sqrt(beta)) * std::exp(-0.1 * reynolds) +
                                     0.3314 * std::sqrt(beta))
                           : 6.46 * 0.0524 * std::sqrt(beta * reynolds);
    return 3.0 / (2.0 * std::numbers::pi * std::sqrt(shearReynolds)) * cld;
}

/// Lift per unit effective mass (density ρp + C_A ρf) [m/s²]; slip s = u − v.
inline Vec3 liftAcceleration(LiftModel model, const Vec3& slip, const Vec3& fluidVorticity,
                             const Vec3& spin, double particleRadius, double kinematicViscosity,
                             double fluidDensity, double effectiveDensity) {
    Vec3 acceleration = Vec3::Zero();
    const double densityRatio = fluidDensity / effectiveDensity;
    if (usesShearLift(model)) {
        const double diameter = particleDiameter(particleRadius);
        const double reynolds = particleReynolds(slip.norm(), particleRadius, kinematicViscosity);
        const double shearReynolds =
            fluidVorticity.norm() * diameter * diameter / kinematicViscosity;
        acceleration += densityRatio * saffmanMeiCoefficient(reynolds, shearReynolds) *
                        slip.cross(fluidVorticity);
    }
    if (usesSpinLift(model)) {
        // π R³ ρf Ω × (v − u) / (4/3 π R³ ρ_e) = ¾ (ρf/ρ_e) s × Ω.
        acceleration += 0.75 * densityRatio * slip.cross(spin - 0.5 * fluidVorticity);
    }
    return acceleration;
}

} // namespace slides
