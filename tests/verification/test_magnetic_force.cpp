// ctest-labels: electromagnetic physics
// Magnetic particles in an applied field (Section 2.7.2, Eq. 2.99–2.110; physics/magnetic_force.h)
// in the field of a circular current loop, computed here by Biot–Savart quadrature (an
// independent route to B and, by central differences, ∇B):
//  - the quadrature against the closed form on the axis, B_z = µ0 I a²/(2 (a² + z²)^(3/2));
//  - the force on a linear paramagnetic sphere on the axis against the closed form of Eq. 2.110,
//    F_z = χ V/(µ0 µr) B_z dB_z/dz: drawn towards the loop, a diamagnetic one pushed away;
//  - off the axis, the force is −∇ of the energy −χ V |B|²/(2 µ0 µr) (B is curl-free there);
//  - a fixed moment along the axis feels m_z dB_z/dz (Eq. 2.102);
//  - the loop's field anywhere (physics/current_loop.h, Jackson's elliptic-integral form and
//    the off-axis series near the axis) and its gradient against the quadrature, free of
//    divergence and curl, the two forms agreeing where they switch, any loop's frame.
#include "slides/physics/current_loop.h"
#include "slides/physics/magnetic_force.h"

#include <Eigen/Geometry>
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

/// ∇B by fourth-order central differences of the quadrature, step δ = 1e-4 a: truncation
/// ~(δ/d)⁴ relative at a distance d from the wire (1e-14 at d = a, 1e-11 at d = 0.1 a),
/// round-off ~1e-16 a/δ = 1e-12.
Mat3 biotSavartGradient(const Vec3& x) {
    const double delta = 1e-4 * loopRadius;
    Mat3 gradient;
    for (int j = 0; j < 3; ++j) {
        const Vec3 step = delta * Vec3::Unit(j);
        gradient.col(j) = (8 * (biotSavart(x + step) - biotSavart(x - step)) -
                           (biotSavart(x + 2 * step) - biotSavart(x - 2 * step))) /
                          (12 * delta);
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

/// The loop of biotSavart: centre 0, axis +z.
CurrentLoop standardLoop() {
    CurrentLoop loop;
    loop.radius = loopRadius;
    loop.current = current;
    return loop;
}

/// Points (ρ, z)/a on the axis, beside it on both sides of the series' switch at
/// ρ = 1e-3 √(a² + z²), in the loop's plane inside and outside, next to the wire, and far.
const double pointsOverRadius[][2] = {{0, 0},      {0, 0.7},     {1e-4, 0.3}, {8e-4, -0.5},
                                      {2e-3, 0.2}, {0.01, -0.4}, {0.5, 0},    {2, 0},
                                      {0.9, 0.05}, {1.3, -0.8},  {3, 4}};

Vec3 pointAt(const double (&over)[2], double azimuth) {
    return loopRadius * Vec3(over[0] * std::cos(azimuth), over[0] * std::sin(azimuth), over[1]);
}

TEST(CurrentLoopField, MatchesBiotSavartOnAndOffTheAxis) {
    // Quadrature to round-off (geometric convergence; the nearest point is 0.11 a from the
    // wire); the closed form's error is the series' (ρ/s)⁴ ≤ 1e-12 or the elliptic bracket's
    // cancellation 1e-16/m: B within 1e-10 of |B|. ∇B against the quadrature's central
    // differences (their error ≤ 1e-11): 1e-9 of |B|/a, the gradient's scale (∇B = 0 at the
    // loop's centre).
    for (const auto& over : pointsOverRadius) {
        const Vec3 x = pointAt(over, 0.7);
        const MagneticFieldSample closed = loopField(standardLoop(), x);
        const Vec3 quadrature = biotSavart(x);
        EXPECT_LT((closed.field - quadrature).norm() / quadrature.norm(), 1e-10)
            << "(ρ, z)/a = (" << over[0] << ", " << over[1] << ")";
        const Mat3 gradient = biotSavartGradient(x);
        EXPECT_LT((closed.gradient - gradient).norm() / (quadrature.norm() / loopRadius), 1e-9)
            << "(ρ, z)/a = (" << over[0] << ", " << over[1] << ")";
    }
}

TEST(CurrentLoopField, IsFreeOfDivergenceAndCurl) {
    // Off the wire ∇·B = 0 and ∇ × B = 0: the trace and the antisymmetric part of ∇B, whose
    // nine entries come from four independent derivatives, vanish to round-off (1e-12 of |B|/a).
    for (const auto& over : pointsOverRadius) {
        const MagneticFieldSample sample = loopField(standardLoop(), pointAt(over, 2.1));
        const Mat3& gradient = sample.gradient;
        const double scale = sample.field.norm() / loopRadius;
        EXPECT_LT(std::abs(gradient.trace()) / scale, 1e-12)
            << "(ρ, z)/a = (" << over[0] << ", " << over[1] << ")";
        EXPECT_LT((gradient - gradient.transpose()).norm() / scale, 1e-12)
            << "(ρ, z)/a = (" << over[0] << ", " << over[1] << ")";
    }
}

TEST(CurrentLoopField, SeriesAndEllipticFormAgreeWhereTheySwitch) {
    // Either side of ρ = 1e-3 √(a² + z²), 1e-9 apart (a change of ~1e-12 in the field): the two
    // forms agree to 1e-11 of |B| and 1e-10 of |B|/a (the elliptic form's derivatives keep the
    // bracket's cancellation there: measured up to 3.4e-11).
    for (const double z : {-0.6 * loopRadius, 0.0, 0.25 * loopRadius, 5 * loopRadius}) {
        const double edge = 1e-3 * std::hypot(loopRadius, z);
        const MagneticFieldSample series = loopField(standardLoop(), Vec3(edge * (1 - 1e-9), 0, z));
        const MagneticFieldSample elliptic =
            loopField(standardLoop(), Vec3(edge * (1 + 1e-9), 0, z));
        EXPECT_LT((series.field - elliptic.field).norm() / elliptic.field.norm(), 1e-11)
            << "z/a " << z / loopRadius;
        EXPECT_LT((series.gradient - elliptic.gradient).norm() /
                      (elliptic.field.norm() / loopRadius),
                  1e-10)
            << "z/a " << z / loopRadius;
    }
}

TEST(CurrentLoopField, TurnsAndMovesWithItsLoop) {
    // A loop at c with axis n = R e_z: B(c + R x) = R B0(x) and ∇B = R ∇B0 Rᵀ, for the
    // standard loop's B0 (the field is symmetric about the axis, so any R taking e_z to n).
    CurrentLoop tilted = standardLoop();
    tilted.centre = Vec3(0.3, -0.1, 0.02);
    tilted.axis = Vec3(1, -2, 0.5).normalized();
    const Mat3 turn =
        Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), tilted.axis).toRotationMatrix();
    for (const auto& over : pointsOverRadius) {
        const Vec3 x = pointAt(over, -1.2);
        const MagneticFieldSample standard = loopField(standardLoop(), x);
        const MagneticFieldSample turned = loopField(tilted, tilted.centre + turn * x);
        EXPECT_LT((turned.field - turn * standard.field).norm() / standard.field.norm(), 1e-12);
        EXPECT_LT((turned.gradient - turn * standard.gradient * turn.transpose()).norm() /
                      (standard.field.norm() / loopRadius),
                  1e-11)
            << "(ρ, z)/a = (" << over[0] << ", " << over[1] << ")";
    }
}

} // namespace
} // namespace slides
