// Magnetic particles in an applied field: the force on a magnetic moment and on a linear
// paramagnetic (or diamagnetic) sphere in a field gradient, and the field of a circular current
// loop on its axis to verify them against.
//
// Reference: Section 2.7.2, Eq. 2.99–2.110. A moment µm in a field B has the energy −µm·B
// (Eq. 2.101) and feels F = ∇(µm·B) = (∇B)ᵀ µm (Eq. 2.102, µm held fixed; (∇B)ᵢⱼ = ∂Bᵢ/∂xⱼ).
// A linear material magnetises as M = χm H (Eq. 2.107) with B = µ0 µr H, µr = 1 + χm
// (Eq. 2.108); a small particle of volume V carries µm = M V along B (Eq. 2.109), so
// F = χm V/(µ0 µr) (∇B)ᵀ B = χm V/(µ0 µr) |B| ∂|B|/∂n (Eq. 2.110): drawn into the stronger field
// for χm > 0, pushed out of it for χm < 0. On the axis of a loop of radius a carrying current I
// (Biot–Savart): B_z(z) = µ0 I a²/(2 (a² + z²)^(3/2)).
#pragma once

#include "slides/core/vector.h"

#include <cmath>
#include <numbers>

namespace slides {

/// µ0, the magnetic constant [T m/A] (CODATA 2018: 1.25663706212e-6).
constexpr double vacuumPermeability = 1.25663706212e-6;

/// F = (∇B)ᵀ µm on a fixed moment µm [A m²] in a field of gradient ∇B [T/m] (Eq. 2.102) [N].
inline Vec3 momentForce(const Vec3& moment, const Mat3& fieldGradient) {
    return fieldGradient.transpose() * moment;
}

/// µm = χm V B/(µ0 µr) of a linear sphere of volume V [m³] in B [T] (Eq. 2.107–2.109) [A m²].
inline Vec3 inducedMoment(double susceptibility, double volume, const Vec3& field) {
    return susceptibility * volume / (vacuumPermeability * (1 + susceptibility)) * field;
}

/// The force on a linear paramagnetic (χm > 0) or diamagnetic sphere of volume V in B with
/// gradient ∇B (Eq. 2.110) [N].
inline Vec3 paramagneticForce(double susceptibility, double volume, const Vec3& field,
                              const Mat3& fieldGradient) {
    return momentForce(inducedMoment(susceptibility, volume, field), fieldGradient);
}

/// The force per unit mass on a linear sphere of density ρp [kg/m³] (Eq. 2.110 over m = ρp V)
/// [m/s²].
inline Vec3 paramagneticAcceleration(double susceptibility, double density, const Vec3& field,
                                     const Mat3& fieldGradient) {
    return paramagneticForce(susceptibility, 1 / density, field, fieldGradient);
}

/// B_z on the axis of a circular loop of radius a [m] carrying current I [A], at distance z
/// from its plane [T].
inline double loopAxisField(double current, double loopRadius, double z) {
    const double a2 = loopRadius * loopRadius;
    return vacuumPermeability * current * a2 / (2 * std::pow(a2 + z * z, 1.5));
}

/// dB_z/dz on the loop's axis [T/m].
inline double loopAxisFieldSlope(double current, double loopRadius, double z) {
    const double a2 = loopRadius * loopRadius;
    return -1.5 * vacuumPermeability * current * a2 * z / std::pow(a2 + z * z, 2.5);
}

} // namespace slides
