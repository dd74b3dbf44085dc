// Stresses beneath the surface of an elastic half-space loaded by a contact: Boussinesq's and
// Cerruti's point loads, and the Hertzian normal and tangential tractions over a contact circle.
//
// Reference: Johnson, Contact Mechanics (1985), Eq. 3.19–3.20 (point loads), Eq. 3.44–3.45
// (the Hertz axis); Hamilton, Proc. IMechE 197C (1983) 53–59, the explicit normal-Hertz field;
// Hamilton & Goodman, J. Appl. Mech. 33 (1966) 371–376, the tangential Hertz traction
// q = μ p of a sliding contact. The reference's Section 5.2.2 applies these to each impact.
//
// Frame: the contact's centre at the origin, x along the tangential load, z the depth into the
// solid (z ≥ 0); tension positive. A normal load P presses into the solid (P > 0), a tangential
// load Q pulls the surface toward +x. The normal Hertz field is Hamilton's closed form; the
// tangential one superposes Cerruti's point loads over the circle, q(r) = 3Q/(2πa²)·√(1 − r²/a²),
// by a product Gauss rule; far from the contact (distance > farFieldRadii·a) both are the point
// loads' fields, whose relative error there is O((a/ρ)²).
#pragma once

#include "slides/core/vector.h"

#include <span>

namespace slides {

/// A contact's loads on the half-space [N] and its contact radius a [m].
struct HertzLoad {
    double normal = 0;     ///< P, pressing into the solid
    double tangential = 0; ///< Q, along +x of the contact frame
    double radius = 0;     ///< a
};

/// Boussinesq's field of a normal point load P at the origin (Johnson Eq. 3.20) [Pa].
Mat3 boussinesqStress(double normalLoad, const Vec3& point, double poisson);

/// Cerruti's field of a tangential point load Q along +x at the origin (Johnson Eq. 3.19) [Pa].
Mat3 cerrutiStress(double tangentialLoad, const Vec3& point, double poisson);

/// The field of the Hertz pressure p = p0 √(1 − r²/a²), p0 = 3P/(2πa²) (Hamilton 1983) [Pa].
Mat3 hertzNormalStress(double normalLoad, double contactRadius, const Vec3& point, double poisson);

/// The field of the Hertzian traction q = (3Q/2πa²) √(1 − r²/a²) along +x (Hamilton & Goodman
/// 1966), by Cerruti's point loads over the circle [Pa]. Accurate to 1e-3 of p0 at depths
/// beyond a/4 (tests/verification/test_half_space_stress.cpp); the traction's own singular
/// surface layer is smeared over the quadrature's spacing.
Mat3 hertzTangentialStress(double tangentialLoad, double contactRadius, const Vec3& point,
                           double poisson);

/// A point of the quadrature over the unit circle: position (x, y) and the fraction of a
/// Hertzian traction ∝ √(1 − r²) that it carries (the fractions sum to 1).
struct CirclePoint {
    double x, y, weight;
};
/// Gauss–Legendre in u = √(1 − r²) (the traction's square-root edge made smooth), the periodic
/// trapezoid rule in the angle.
std::span<const CirclePoint> hertzCircle();

/// The field of a Hertzian traction of total load over the circle of contactRadius, superposed
/// from pointField(load, point), the field of a point load at the origin.
template <class PointField>
Mat3 overHertzCircle(double load, double contactRadius, const Vec3& point, PointField pointField) {
    Mat3 stress = Mat3::Zero();
    for (const CirclePoint& source : hertzCircle())
        stress +=
            pointField(source.weight * load, Vec3(point.x() - contactRadius * source.x,
                                                  point.y() - contactRadius * source.y, point.z()));
    return stress;
}

/// Distance from the contact's centre, in contact radii, beyond which contactStress takes the
/// point loads' fields.
inline constexpr double farFieldRadii = 10.0;

/// The field of a contact's normal and tangential Hertz loads: Hertzian tractions near the
/// contact, point loads beyond farFieldRadii·a [Pa].
Mat3 contactStress(const HertzLoad& load, const Vec3& point, double poisson);

} // namespace slides
