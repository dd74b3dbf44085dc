// Kim's acceleration factor G of the finite-Reynolds history kernel (Eq. 3.10–3.11), from the
// relative acceleration of particle and fluid.
//
// Reference: Eq. 3.9–3.15 of the reference; Kim, Elghobashi & Sirignano (1998, J. Fluid Mech.
// 367:221). G scales the long-lag term of Kim's kernel (physics/history_kernel.h kimKernel):
//   G = 1/(1 + β √MA1)                                                        (Eq. 3.10)
//   β = c2 / (1 + φ_r·φ_r^c4 / [c3 (φ_r + φ_r^c4)]),  φ_r = MA2/MA1              (Eq. 3.11)
// (read as printed in the reference), with the dimensionless relative accelerations of the slip
// speed s = |u − v|,
//   MA1 = 2R |ds/dt| / s²,   MA2 = 4R² |d²s/dt²| / s³,
// and c2 = 22, c3 = 0.07, c4 = 0.25 (Eq. 3.15). G = 1 at zero relative acceleration: the kernel
// is Kim's steady one; G < 1 delays the kernel's long-lag decay, never its short-lag, Basset
// part.
#pragma once

#include "slides/physics/history_kernel.h"

#include <cmath>

namespace slides {

/// MA1 = 2R |ds/dt|/s² for the slip speed s and its rate of change [-].
inline double kimFirstAcceleration(double particleRadius, double slipSpeed, double slipRate) {
    return 2 * particleRadius * std::abs(slipRate) / (slipSpeed * slipSpeed);
}

/// MA2 = 4R² |d²s/dt²|/s³ [-].
inline double kimSecondAcceleration(double particleRadius, double slipSpeed, double slipCurvature) {
    return 4 * particleRadius * particleRadius * std::abs(slipCurvature) /
           (slipSpeed * slipSpeed * slipSpeed);
}

/// β of Eq. 3.11 for φ_r = MA2/MA1: c2 at φ_r = 0, falling towards 0 as φ_r grows.
inline double kimBeta(double accelerationRatio) {
    using C = KimCoefficients;
    if (!(accelerationRatio > 0)) return C::c2;
    const double power = std::pow(accelerationRatio, C::c4);
    return C::c2 / (1 + accelerationRatio * power / (C::c3 * (accelerationRatio + power)));
}

/// G of Eq. 3.10 for MA1 and MA2: 1 when MA1 = 0.
inline double kimAccelerationFactor(double firstAcceleration, double secondAcceleration) {
    if (!(firstAcceleration > 0)) return 1.0;
    return 1 / (1 + kimBeta(secondAcceleration / firstAcceleration) * std::sqrt(firstAcceleration));
}

} // namespace slides
