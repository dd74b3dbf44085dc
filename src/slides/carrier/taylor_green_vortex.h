// TaylorGreenVortex: the decaying Taylor–Green vortex, an exact unsteady solution of the
// Navier–Stokes equations (Taylor & Green 1937, Proc. R. Soc. A 158:499), in the x–y plane,
// uniform along z, with wavenumber k = 2π/L and decay F(t) = exp(−2νk²t):
//   u = U sin kx cos ky F,   v = −U cos kx sin ky F,   w = 0,
//   p/ρ = (U²/4)(cos 2kx + cos 2ky) F²,
// so DU/Dt = ∂U/∂t + (U·∇)U = −∇p/ρ + ν∇²U with ∂U/∂t = −2νk²U and ∇²U = −2k²U: the carrier
// for the time derivative and the pressure-gradient term of Eq. 3.3.
//
//     carrier { type taylorGreenVortex; taylorGreenVortexCoeffs { velocity 1; wavelength 0.01; } }
#pragma once

#include "slides/carrier/unsteady_analytic_carrier.h"

namespace slides {

class TaylorGreenVortex final : public UnsteadyAnalyticCarrier {
public:
    /// velocity U [m/s], wavelength L [m], kinematic viscosity ν [m²/s], gas temperature [K].
    TaylorGreenVortex(double velocity, double wavelength, double viscosity, double temperature);

    void sample(std::span<const Vec3> points, double time, CarrierNeeds needs,
                CarrierSample& out) const override;
    std::string describe() const override;

    /// U(x, t) [m/s].
    Vec3 velocity(const Vec3& x, double time) const;
    /// ∇p/ρ at (x, t) from the closed-form pressure [m/s²].
    Vec3 kinematicPressureGradient(const Vec3& x, double time) const;

private:
    double velocity_, wavenumber_, viscosity_;
};

} // namespace slides
