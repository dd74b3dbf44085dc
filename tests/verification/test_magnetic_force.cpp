// ctest-labels: electromagnetic physics
// Magnetic particles in an applied field (Section 2.7.2, Eq. 2.99–2.110; physics/magnetic_force.h)
// in the field of a circular current loop, computed here by Biot–Savart quadrature (an
// independent route to B and, by central differences, ∇B):
//  - the quadrature against the closed form on the axis, B_z = µ0 I a²/(2 (a² + z²)^(3/2));
//  - the force on a linear paramagnetic sphere on the axis against the closed form of Eq. 2.110,
//    F_z = χ V/(µ0 µr) B_z dB_z/dz: drawn towards the loop, a diamagnetic one pushed away;
//  - off the axis, the force is −∇ of the energy −χ V |B|²/(2 µ0 µr) (B is curl-free there);
//  - a fixed moment along the axis feels m_z dB_z/dz (Eq. 2.102).
#include "slides/physics/magnetic_force.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace slides {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double loopRadius = 0.05, current = 200.0; // a [m], I [A]

/// B of the loop (radius a, centre 0, in the xy-plane, current anticlockwise about +z) at x by
/// the midpoint rule over 4000 segments of dB = µ0 I/(4π) dl × (x − x')/|x − x'|³: the
/// integrand is smooth and periodic, so the rule converges geometrically (to round-off here).
Vec3 biotSavart(const Vec3& x) {
    const int segments = 4000;
    Vec3 field = Vec3::Zero();
    for (int k = 0; k < segments; ++k) {
        const double angle = 2 * pi * (k + 0.5) / segments;
        const Vec3 source(loopRadius * std::cos(angle), loopRadius * std::sin(angle), 0);
        const Vec3 dl = 2 * pi * loopRadius / segments * Vec3(-std::sin(angle), std::cos(angle), 0);
        const Vec3 r = x - source;
        field += dl.cross(r) / std::pow(r.norm(), 3);
    }
    return vacuumPermeability * current / (4 * pi) * field;
}

/// ∇B by central differences of the quadrature, step δ = 1e-4 a: truncation ~δ²/a² ≈ 1e-8
/// relative, round-off ~1e-16 a/δ = 1e-12.
Mat3 biotSavartGradient(const Vec3& x) {
    const double delta = 1e-4 * loopRadius;
    Mat3 gradient;
    for (int j = 0; j < 3; ++j) {
        const Vec3 step = delta * Vec3::Unit(j);
        gradient.col(j) = (biotSavart(x + step) - biotSavart(x - step)) / (2 * delta);
    }
    return gradient;
}

TEST(CurrentLoop, QuadratureMatchesTheAxisField) {
    for (const double z : {0.0, 0.3 * loopRadius, 2.0 * loopRadius}) {
        const Vec3 field = biotSavart(Vec3(0, 0, z));
        EXPECT_NEAR(field.z() / loopAxisField(current, loopRadius, z), 1.0, 1e-12) << "z " << z;
        EXPECT_LT(field.head<2>().norm() / field.z(), 1e-12) << "z " << z;
    }
}

TEST(ParamagneticForce, OnTheLoopAxisIsTheClosedFormOfEq2_110) {
    const double radius = 20e-6, volume = 4.0 / 3.0 * pi * radius * radius * radius;
    for (const double susceptibility : {0.5, 1e-3, -1e-5}) { // magnetite-like, para-, dia-
        for (const double z : {0.2 * loopRadius, 1.0 * loopRadius, 3.0 * loopRadius}) {
            const Vec3 x(0, 0, z);
            const Vec3 force =
                paramagneticForce(susceptibility, volume, biotSavart(x), biotSavartGradient(x));
            const double exact =
                susceptibility * volume / (vacuumPermeability * (1 + susceptibility)) *
                loopAxisField(current, loopRadius, z) * loopAxisFieldSlope(current, loopRadius, z);
            EXPECT_NEAR(force.z() / exact, 1.0, 1e-6) << "χ " << susceptibility << ", z " << z;
            EXPECT_LT(force.head<2>().norm() / std::abs(exact), 1e-6);
            // Towards the loop (−z) for χ > 0, away for χ < 0.
            EXPECT_EQ(force.z() < 0, susceptibility > 0);
        }
    }
}

TEST(ParamagneticForce, IsMinusTheGradientOfItsEnergyOffTheAxis) {
    // U = −χ V |B|²/(2 µ0 µr): F = −∇U = χ V/(µ0 µr) (∇B)ᵀ B where ∇ × B = 0 (off the wire).
    const double susceptibility = 0.2, volume = 1e-12;
    const Vec3 x(0.4 * loopRadius, -0.25 * loopRadius, 0.6 * loopRadius);
    const auto energy = [&](const Vec3& at) {
        return -susceptibility * volume * biotSavart(at).squaredNorm() /
               (2 * vacuumPermeability * (1 + susceptibility));
    };
    const double delta = 1e-4 * loopRadius;
    Vec3 minusGradient;
    for (int j = 0; j < 3; ++j)
        minusGradient[j] =
            -(energy(x + delta * Vec3::Unit(j)) - energy(x - delta * Vec3::Unit(j))) / (2 * delta);
    const Vec3 force =
        paramagneticForce(susceptibility, volume, biotSavart(x), biotSavartGradient(x));
    EXPECT_LT((force - minusGradient).norm() / minusGradient.norm(), 1e-6);
}

TEST(MomentForce, OfAFixedMomentAlongTheAxisIsItsTimesTheSlope) {
    const double z = 0.7 * loopRadius, moment = 3e-4; // [A m²]
    const Vec3 x(0, 0, z);
    const Vec3 force = momentForce(Vec3(0, 0, moment), biotSavartGradient(x));
    EXPECT_NEAR(force.z() / (moment * loopAxisFieldSlope(current, loopRadius, z)), 1.0, 1e-6);
}

} // namespace
} // namespace slides
