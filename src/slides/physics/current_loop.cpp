#include "slides/physics/current_loop.h"

#include "slides/physics/magnetic_force.h"

#include <unsupported/Eigen/AutoDiff>

#include <cmath>
#include <numbers>

namespace slides {

namespace {

/// A value with its partial derivatives along (ρ, z).
using Dual = Eigen::AutoDiffScalar<Eigen::Vector2d>;

/// The complete elliptic integrals K(m) and E(m) of the parameter m = k², 0 < m < 1, with
/// their derivatives carried along. Both from one arithmetic–geometric mean (Abramowitz &
/// Stegun 17.6.1–17.6.4): a₀ = 1, b₀ = √(1 − m), c₀² = m, a, b → (a + b)/2, √(ab),
/// c = (a − b)/2; K = π/(2 a_N), E = K (1 − Σ 2ⁿ⁻¹ cₙ²). Quadratic convergence: five or six
/// rounds to a relative 4e-16 below m = 0.999 (the cap of 40 is never reached).
void ellipticIntegrals(const Dual& m, Dual& first, Dual& second) {
    const double p = m.value();
    double a = 1, b = std::sqrt(1 - p), sum = 0.5 * p, weight = 0.5;
    for (int round = 0; round < 40 && a - b > 4e-16 * a; ++round) { // b ≤ a throughout
        const double c = 0.5 * (a - b);
        weight *= 2;
        sum += weight * c * c;
        const double mean = 0.5 * (a + b);
        b = std::sqrt(a * b);
        a = mean;
    }
    const double k = std::numbers::pi / (2 * a), e = k * (1 - sum);
    first = Dual(k, (e - (1 - p) * k) / (2 * p * (1 - p)) * m.derivatives());
    second = Dual(e, (e - k) / (2 * p) * m.derivatives());
}

/// B_ρ/ρ (finite on the axis), B_ρ and B_z of the loop in its own frame.
struct CylindricalField {
    Dual radialOverRho, radial, axial;
};

/// Jackson's elliptic form (see the header), off the axis.
CylindricalField ellipticForm(double a, double current, const Dual& rho, const Dual& z) {
    using std::sqrt;
    const Dual r2 = rho * rho + z * z;
    const Dual alpha2 = a * a + r2 - 2 * a * rho, beta2 = a * a + r2 + 2 * a * rho;
    const Dual beta = sqrt(beta2);
    Dual k, e;
    ellipticIntegrals(1 - alpha2 / beta2, k, e);
    const double c = vacuumPermeability * current / std::numbers::pi;
    const Dual radialOverRho =
        c * z / (2 * alpha2 * beta * rho * rho) * ((a * a + r2) * e - alpha2 * k);
    return {radialOverRho, radialOverRho * rho,
            c / (2 * alpha2 * beta) * ((a * a - r2) * e + alpha2 * k)};
}

/// The off-axis series of the axis field B0(z) (see the header), near the axis.
CylindricalField axisSeries(double a, double current, const Dual& rho, const Dual& z) {
    using std::pow;
    const Dual s2 = a * a + z * z;
    const double scale = vacuumPermeability * current * a * a / 2;
    const Dual slope = -3 * scale * z * pow(s2, -2.5);                        // B0'
    const Dual curvature = scale * (12 * z * z - 3 * a * a) * pow(s2, -3.5);  // B0''
    const Dual third = scale * z * (45 * a * a - 60 * z * z) * pow(s2, -4.5); // B0'''
    const Dual fourth = scale * (45 * a * a * a * a - 540 * a * a * z * z + 360 * z * z * z * z) *
                        pow(s2, -5.5); // B0''''
    const Dual rho2 = rho * rho;
    const Dual radialOverRho = -0.5 * slope + rho2 / 16 * third;
    return {radialOverRho, radialOverRho * rho,
            scale * pow(s2, -1.5) - rho2 / 4 * curvature + rho2 * rho2 / 64 * fourth};
}

} // namespace

MagneticFieldSample loopField(const CurrentLoop& loop, const Vec3& x) {
    const Vec3& n = loop.axis;
    const Vec3 offset = x - loop.centre;
    const double height = offset.dot(n);
    const Vec3 across = offset - height * n;
    const double distance = across.norm();
    // ρ̂: any unit vector across the axis where ρ = 0 (the field's gradient does not depend on
    // it there).
    const Vec3 outward = distance > 0 ? Vec3(across / distance) : n.unitOrthogonal();
    const double a = loop.radius;
    const Dual rho(distance, 2, 0), z(height, 2, 1);
    const CylindricalField f = distance < 1e-3 * std::hypot(a, height)
                                   ? axisSeries(a, loop.current, rho, z)
                                   : ellipticForm(a, loop.current, rho, z);
    // B = B_ρ ρ̂ + B_z n; ∂ρ̂/∂x = (I − nnᵀ − ρ̂ρ̂ᵀ)/ρ.
    MagneticFieldSample sample;
    sample.field = f.radial.value() * outward + f.axial.value() * n;
    const Mat3 across2 = Mat3::Identity() - n * n.transpose() - outward * outward.transpose();
    sample.gradient = outward * (f.radial.derivatives()(0) * outward.transpose() +
                                 f.radial.derivatives()(1) * n.transpose()) +
                      f.radialOverRho.value() * across2 +
                      n * (f.axial.derivatives()(0) * outward.transpose() +
                           f.axial.derivatives()(1) * n.transpose());
    return sample;
}

} // namespace slides
