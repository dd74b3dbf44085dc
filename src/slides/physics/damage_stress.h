// The damage-equivalent stress of Lemaitre & Desmorat: the triaxiality function R_ν (Eq. 5.4),
// the equivalent stress σ_eq = σ_vm √R_ν (Eq. 5.5) and the damage indicator Σ (Eq. 5.6).
//
// Reference: Lemaitre & Desmorat, Engineering Damage Mechanics (2005) §1.4; the reference's
// Section 5.2.3. σ_dil is the hydrostatic stress tr σ / 3, with which σ_eq²/(2E) is the elastic
// strain energy density (tests/verification/test_porous_damage.cpp). A grid point counts an
// impact as damaging when Σ > 0, i.e. σ_eq > σ₀ (surfaces/erosion_grid.h).
#pragma once

#include "slides/core/vector.h"

#include <algorithm>
#include <cmath>

namespace slides {

/// σ_vm = √(3/2 s:s), s the deviator [Pa].
inline double vonMisesStress(const Mat3& stress) {
    const Mat3 deviator = stress - stress.trace() / 3 * Mat3::Identity();
    return std::sqrt(1.5 * deviator.squaredNorm());
}

/// σ_dil = tr σ / 3 [Pa].
inline double dilatationalStress(const Mat3& stress) { return stress.trace() / 3; }

/// Eq. 5.4: R_ν = 2/3 (1 + ν) + 3 (1 − 2ν) (σ_dil/σ_vm)².
inline double triaxialityFunction(double dilatational, double vonMises, double poisson) {
    const double ratio = dilatational / vonMises;
    return 2.0 / 3 * (1 + poisson) + 3 * (1 - 2 * poisson) * ratio * ratio;
}

/// Eq. 5.5: σ_eq = σ_vm √R_ν, as √(σ_vm² R_ν), finite where σ_vm = 0 (a hydrostatic stress).
inline double equivalentStress(const Mat3& stress, double poisson) {
    const double vonMises = vonMisesStress(stress), dilatational = dilatationalStress(stress);
    return std::sqrt(2.0 / 3 * (1 + poisson) * vonMises * vonMises +
                     3 * (1 - 2 * poisson) * dilatational * dilatational);
}

/// Eq. 5.6: Σ = (σ_eq − σ₀ + |σ_eq − σ₀|)/(2σ₀), zero below the threshold σ₀.
inline double damageIndicator(double equivalent, double threshold) {
    return std::max(equivalent - threshold, 0.0) / threshold;
}

} // namespace slides
