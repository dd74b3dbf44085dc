// The magnetic field of a circular current loop (a thin coil) anywhere in space, with its
// gradient: the applied field of magnetic separation and focusing, and a field with a gradient
// for the force on magnetic particles (physics/magnetic_force.h).
//
// Reference: Section 2.7.2 (the field a magnetic particle feels); the closed form of the loop's
// field by complete elliptic integrals of the parameter m = k² (Jackson, Classical
// Electrodynamics, 3rd ed., Eq. 5.37; in Simpson, Lane, Immer & Youngquist, NASA/TM-2013-217919,
// "Simple analytic expressions for the magnetic field of a circular current loop"), for a loop
// of radius a in the plane z = 0 carrying the current I anticlockwise about +z, at a distance ρ
// from the axis (r² = ρ² + z²):
//   α² = a² + r² − 2aρ,   β² = a² + r² + 2aρ,   m = 1 − α²/β²,   C = µ0 I/π,
//   B_ρ = C z/(2α²βρ) [(a² + r²) E(m) − α² K(m)],   B_z = C/(2α²β) [(a² − r²) E(m) + α² K(m)].
// Near the axis the bracket of B_ρ cancels to O(m²), so within ρ < 1e-3 √(a² + z²) the
// off-axis series of the axis field B0(z) = µ0 I a²/(2 (a² + z²)^(3/2)) is taken instead:
//   B_z = B0 − ρ²/4 B0'' + ρ⁴/64 B0'''',   B_ρ = −ρ/2 B0' + ρ³/16 B0''',
// whose divergence and curl vanish to O(ρ⁴) (relative error ~(ρ/√(a² + z²))⁴ ≤ 1e-12).
// The partial derivatives come with the values by forward-mode differentiation (Eigen's
// AutoDiffScalar; dK/dm = (E − (1 − m) K)/(2m(1 − m)), dE/dm = (E − K)/(2m)). The field
// diverges on the wire itself, where a real coil's winding has its cross-section.
//
//     physics { electromagnetic { coils { inner { centre (0 0 0); axis (0 0 1); radius 0.05;
//                                                 current 2000; } } } }   // current in A-turns
#pragma once

#include "slides/core/vector.h"

#include <string>

namespace slides {

/// A circular current loop: a coil whose winding is thin against its radius.
struct CurrentLoop {
    std::string name;           ///< its key in physics.electromagnetic.coils
    Vec3 centre = Vec3::Zero(); ///< [m]
    Vec3 axis = Vec3::UnitZ();  ///< unit normal; the current circulates anticlockwise about it
    double radius = 0;          ///< a [m]
    double current = 0;         ///< I [A] (the ampere-turns of a coil of many turns)
};

/// A magnetic field and its gradient at a point.
struct MagneticFieldSample {
    Vec3 field = Vec3::Zero();    ///< B [T]
    Mat3 gradient = Mat3::Zero(); ///< (∇B)ᵢⱼ = ∂Bᵢ/∂xⱼ [T/m]
};

/// The loop's field and gradient at x.
MagneticFieldSample loopField(const CurrentLoop& loop, const Vec3& x);

} // namespace slides
