// Added mass and pressure gradient (fluid acceleration) of the Maxey–Riley equation.
//
// Reference: Eq. 3.2–3.4 of the reference (Maxey & Riley 1983, Phys. Fluids 26:883; Auton,
// Hunt & Prud'homme 1988 for C_A = ½ of a sphere). With added mass the particle's inertia is
// m_e = m_p + C_A m_f, and the fluid acceleration DU/Dt acts through the pressure gradient
// (m_f DU/Dt) and the added mass (C_A m_f DU/Dt):
//   m_e dv/dt = F_drag + F_history + F_lift + (m_f + C_A m_f) DU/Dt + (m_p − m_f) g.
// Every term below is per unit effective mass. DU/Dt = ∂U/∂t + (U·∇)U: for a steady carrier (the
// analytic jets, a frozen OpenFOAM field) only (U·∇)U from the interpolated velocity gradient; an
// unsteady one (carrier/carrier_field.h, steady() false) supplies ∂U/∂t as well.
//
//     physics { addedMass on; pressureGradient on; }   // both off by default
#pragma once

#include "slides/core/vector.h"

namespace slides {

/// C_A of a sphere in potential flow.
inline constexpr double sphereAddedMassCoefficient = 0.5;

/// Which of the fluid-inertia terms are on.
struct FluidInertia {
    bool addedMass = false;
    bool pressureGradient = false;

    double addedMassCoefficient() const { return addedMass ? sphereAddedMassCoefficient : 0.0; }
    /// ρp + C_A ρf: the density that carries the particle's inertia [kg/m³].
    double effectiveDensity(double particleDensity, double fluidDensity) const {
        return particleDensity + addedMassCoefficient() * fluidDensity;
    }
    /// Coefficient of DU/Dt in dv/dt: (pressure gradient + C_A) ρf / (ρp + C_A ρf).
    double fluidAccelerationFactor(double particleDensity, double fluidDensity) const {
        return ((pressureGradient ? 1.0 : 0.0) + addedMassCoefficient()) * fluidDensity /
               effectiveDensity(particleDensity, fluidDensity);
    }
    /// Gravity (with buoyancy, (m_p − m_f) g of Eq. 3.3) per effective mass [m/s²].
    Vec3 bodyAcceleration(const Vec3& gravity, double particleDensity, double fluidDensity,
                          bool buoyancy) const {
        const double weightDensity = buoyancy ? particleDensity - fluidDensity : particleDensity;
        return weightDensity / effectiveDensity(particleDensity, fluidDensity) * gravity;
    }
};

/// Stokes response time with added mass, τ_e = 2 (ρp + C_A ρf) R² / (9 ρf ν) [s].
inline double effectiveResponseTime(double particleDensity, double fluidDensity,
                                    double kinematicViscosity, double particleRadius,
                                    double addedMassCoefficient) {
    return 2.0 * (particleDensity + addedMassCoefficient * fluidDensity) * particleRadius *
           particleRadius / (9.0 * fluidDensity * kinematicViscosity);
}

/// DU/Dt = ∂U/∂t + (U·∇)U of a steady field: gradient(i, j) = dU_i/dx_j, so (U·∇)U = ∇U · U.
inline Vec3 steadyFluidAcceleration(const Vec3& velocity, const Mat3& velocityGradient) {
    return velocityGradient * velocity;
}

/// DU/Dt = ∂U/∂t + (U·∇)U of an unsteady field (Eq. 3.3's fluid acceleration).
inline Vec3 fluidAcceleration(const Vec3& velocity, const Mat3& velocityGradient,
                              const Vec3& velocityTimeDerivative) {
    return velocityTimeDerivative + steadyFluidAcceleration(velocity, velocityGradient);
}

/// Vorticity ∇ × U from the velocity gradient [1/s].
inline Vec3 vorticity(const Mat3& g) {
    return {g(2, 1) - g(1, 2), g(0, 2) - g(2, 0), g(1, 0) - g(0, 1)};
}

} // namespace slides
