// The Coulomb force between two charged particles (Section 2.7.1), truncated at a cut-off
// distance r_c by the shift function of Eq. 2.97.
//
// Reference: Eq. 2.94 (the pair energy q_i q_j / (4π ε0 ε_r r), r = |x_i − x_j|) times the
// truncation T(r) of Eq. 2.97. The extracted text of Eq. 2.97 is garbled; read with the text
// below it (the derivative vanishes at r_c and is continuous) and Brooks et al. (CHARMM, 1983),
// whose shift function it is: T(r) = (1 − r²/r_c²)² for r ≤ r_c, 0 beyond. So, with
// k = 1/(4π ε0 ε_r),
//   U(r) = k q_i q_j (1/r − 2r/r_c² + r³/r_c⁴),
//   F_i  = −∂U/∂x_i = k q_i q_j (1/r² + 2/r_c² − 3r²/r_c⁴) (x_i − x_j)/r,
// which is Coulomb's law k q_i q_j/r² to a relative 2r²/r_c² at small r. Potential and force
// both vanish at r_c, so a pair crossing the cut-off changes neither the energy (the plain cut-off
// of Eq. 2.95 jumps by k q_i q_j/r_c) nor the force (Eq. 2.96's shifted potential keeps a force
// jump k q_i q_j/r_c²): the velocity-Verlet kicks (collide/coulomb_forces.h) then keep the energy
// bounded. The charges are lumped at the centres (Section 2.7.1), which holds while the particles
// are apart: closer than the touching distance R_i + R_j (overlapping, which only a scene without
// contacts allows) the force stays the one at touch, still central (so still conservative, its
// potential continued linearly), and coincident centres feel none, instead of an infinite one.
//
//     physics { electromagnetic { model lorentz; charge { model fixed; value 1e-12; }
//                                 coulomb { model shifted; cutoff 1e-3; permittivity 1; } } }
#pragma once

#include "slides/core/vector.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string_view>

namespace slides {

enum class CoulombModel { none, shifted };

struct CoulombModelName {
    CoulombModel value;
    std::string_view name;
};

/// The name table of the Coulomb interaction. How to add one: an enumerator, its name here, and
/// its pair force and energy below.
constexpr std::array<CoulombModelName, 2> coulombModelNames() {
    return {{{CoulombModel::none, "none"}, {CoulombModel::shifted, "shifted"}}};
}

/// The vacuum permittivity ε0 [F/m] (CODATA 2018).
constexpr double vacuumPermittivity = 8.8541878128e-12;

struct CoulombSettings {
    CoulombModel model = CoulombModel::none;
    double cutoff = 1e-3;    ///< r_c [m]
    double permittivity = 1; ///< ε_r of the gas between the particles

    bool on() const { return model != CoulombModel::none; }
    /// k = 1/(4π ε0 ε_r) [N m²/C²].
    double coulombConstant() const {
        return 1 / (4 * std::numbers::pi * vacuumPermittivity * permittivity);
    }
};

/// The truncated Coulomb pair of Eq. 2.94 × Eq. 2.97: force and energy of two charges at a
/// separation (made by coulombPair).
struct CoulombPair {
    double kCharges; ///< k q_i q_j [N m²]
    double cutoff;   ///< r_c [m]
    double touching; ///< R_i + R_j, at most r_c [m]

    /// The force on particle i, separation = x_i − x_j, closer than the cut-off [N].
    Vec3 forceOn(const Vec3& separation) const {
        const double r = separation.norm();
        if (r == 0) return Vec3::Zero();
        return (magnitude(std::max(r, touching)) / r) * separation;
    }

    /// The pair's potential energy at distance r below the cut-off [J].
    double energy(double r) const {
        const double c2 = cutoff * cutoff;
        const auto shifted = [&](double s) {
            return kCharges * (1 / s - 2 * s / c2 + s * s * s / (c2 * c2));
        };
        if (r >= touching) return shifted(r);
        return shifted(touching) + magnitude(touching) * (touching - r); // linear continuation
    }

private:
    /// −dU/dr at r [N].
    double magnitude(double r) const {
        const double c2 = cutoff * cutoff;
        return kCharges * (1 / (r * r) + 2 / c2 - 3 * r * r / (c2 * c2));
    }
};

/// The pair of particles of charges q_i, q_j [C] and radii R_i, R_j [m].
inline CoulombPair coulombPair(const CoulombSettings& settings, double chargeI, double chargeJ,
                               double radiusI, double radiusJ) {
    // k (q_i q_j), not (k q_i) q_j: the same bits for either order of the pair.
    return {settings.coulombConstant() * (chargeI * chargeJ), settings.cutoff,
            std::min(radiusI + radiusJ, settings.cutoff)};
}

/// The time scale of a pair of charges q at distance s pushing a particle of mass m,
/// τ = √(m s³/(k q²)) [s] (infinite without charge): velocity Verlet's energy error is about
/// 0.6 (h/τ)² (tests/verification/test_coulomb.cpp).
inline double coulombTime(const CoulombSettings& settings, double charge, double mass,
                          double distance) {
    return std::sqrt(mass * distance * distance * distance /
                     (settings.coulombConstant() * charge * charge));
}

} // namespace slides
