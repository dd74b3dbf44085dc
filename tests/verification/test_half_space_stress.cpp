// ctest-labels: erosion
// Sub-surface stresses of an elastic half-space under contact loads (physics/half_space_stress.h,
// the reference's Section 5.2.2), against Johnson, Contact Mechanics (1985):
//  - Hamilton's (1983) normal Hertz field near the axis against Johnson's axis closed forms
//    (Eq. 3.45: σ_z, σ_r) and on the surface against Eq. 3.41 (σ_r, σ_θ, σ_z inside and outside
//    the circle), to 1e-6 p0; the largest shear on the axis 0.31 p0 at z = 0.48 a for ν = 0.3
//    (Johnson §4.2, Fig. 4.3; two printed digits);
//  - every field in equilibrium (∂σ_ij/∂x_j = 0 by central differences) and traction-free on the
//    surface outside its load;
//  - far from the contact, the Hertz fields tend to Boussinesq's and Cerruti's point loads
//    (Eq. 3.19–3.20), with the O((a/ρ)²) error of the load's second moment;
//  - the circle quadrature that superposes Cerruti's point loads for the tangential traction,
//    applied to Boussinesq's, reproduces Hamilton's closed form beyond a/4 in depth to 1e-3 p0.
#include "slides/physics/half_space_stress.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

namespace slides {
namespace {

constexpr double nu = 0.3;
constexpr double load = 1.0;   // P [N]
constexpr double radius = 1.0; // a [m]
const double p0 = 3 * load / (2 * std::numbers::pi * radius * radius);

/// Johnson Eq. 3.45 (on the axis, depth z): σ_z and σ_r = σ_θ.
double axisNormal(double z) { return -p0 / (1 + z * z); }
double axisRadial(double z) {
    return p0 * (-(1 + nu) * (1 - z * std::atan(1 / z)) + 0.5 / (1 + z * z));
}

TEST(HalfSpaceStress, HamiltonNormalFieldNearTheAxisIsJohnsonsAxisSolution) {
    // Off the axis by 3e-4 a the general formula applies (not the axis branch): its values
    // differ from the axis ones by O((r/a)²) ≈ 1e-7 p0.
    for (const double z : {0.05, 0.3, 0.48, 1.0, 2.5, 6.0}) {
        const Mat3 s = hertzNormalStress(load, radius, Vec3(3e-4, 0, z), nu);
        EXPECT_NEAR(s(2, 2), axisNormal(z), 1e-6 * p0) << "z/a = " << z;
        EXPECT_NEAR(s(0, 0), axisRadial(z), 1e-6 * p0) << "z/a = " << z;
        EXPECT_NEAR(s(1, 1), axisRadial(z), 1e-6 * p0) << "z/a = " << z;
    }
}

TEST(HalfSpaceStress, HamiltonNormalFieldOnTheSurfaceIsJohnsonsSurfaceSolution) {
    // Johnson Eq. 3.41, at y = 0 (σ_x = σ_r, σ_y = σ_θ).
    for (const double r : {0.2, 0.5, 0.9, 1.2, 2.0}) {
        const Mat3 s = hertzNormalStress(load, radius, Vec3(r, 0, 0), nu);
        const double inside = r < 1 ? std::sqrt(1 - r * r) : 0.0;
        const double rim = (1 - 2 * nu) / (3 * r * r) * (1 - inside * inside * inside);
        EXPECT_NEAR(s(0, 0), p0 * (rim - inside), 1e-6 * p0) << "r/a = " << r;
        EXPECT_NEAR(s(1, 1), p0 * (-rim - 2 * nu * inside), 1e-6 * p0) << "r/a = " << r;
        EXPECT_NEAR(s(2, 2), -p0 * inside, 1e-6 * p0) << "r/a = " << r;
    }
}

TEST(HalfSpaceStress, LargestShearOnTheAxisIsJohnsons) {
    // τ₁ = (σ_r − σ_z)/2 on the axis, maximised over the depth by a golden-section search.
    const auto shear = [](double z) {
        const Mat3 s = hertzNormalStress(load, radius, Vec3(0, 0, z), nu);
        return 0.5 * (s(0, 0) - s(2, 2));
    };
    double low = 0.1, high = 1.0;
    const double golden = (std::sqrt(5.0) - 1) / 2;
    while (high - low > 1e-9) {
        const double left = high - golden * (high - low), right = low + golden * (high - low);
        if (shear(left) > shear(right))
            high = right;
        else
            low = left;
    }
    EXPECT_NEAR(0.5 * (low + high), 0.48, 0.005);
    EXPECT_NEAR(shear(low) / p0, 0.31, 0.005);
}

/// ∂σ_ij/∂x_j by central differences of step h, relative to the stress scale over h.
Vec3 divergence(const std::function<Mat3(const Vec3&)>& field, const Vec3& point, double h) {
    Vec3 div = Vec3::Zero();
    for (int j = 0; j < 3; ++j) {
        const Vec3 step = h * Vec3::Unit(j);
        div += (field(point + step) - field(point - step)).col(j) / (2 * h);
    }
    return div;
}

TEST(HalfSpaceStress, EveryFieldIsInEquilibriumAndFreeOfTractionOutsideItsLoad) {
    const std::function<Mat3(const Vec3&)> fields[] = {
        [](const Vec3& x) { return boussinesqStress(load, x, nu); },
        [](const Vec3& x) { return cerrutiStress(load, x, nu); },
        [](const Vec3& x) { return hertzNormalStress(load, radius, x, nu); },
        [](const Vec3& x) { return hertzTangentialStress(load, radius, x, nu); },
    };
    const Vec3 points[] = {{0.7, 0.4, 0.6}, {-1.3, 0.9, 1.1}, {2.5, -1.5, 0.8}, {0.2, 0.3, 2.0}};
    for (std::size_t f = 0; f < std::size(fields); ++f) {
        for (const Vec3& point : points) {
            const double h = 1e-4;
            const double scale = fields[f](point).norm() / point.norm();
            // Central differences err by O(h²) of the third derivatives and ~1e-16/h by rounding.
            EXPECT_LT(divergence(fields[f], point, h).norm(), 1e-6 * scale)
                << "field " << f << " at " << point.transpose();
        }
        // On the surface, outside the contact circle: σ_zz = σ_xz = σ_yz = 0.
        const Mat3 surface = fields[f](Vec3(1.7, -0.8, 0));
        EXPECT_NEAR(surface.col(2).norm(), 0.0, 1e-12 * p0) << "field " << f;
    }
}

TEST(HalfSpaceStress, FarFromTheContactTheFieldsAreThePointLoads) {
    // The circle's second moment makes the difference O((a/ρ)²) of the point load's field:
    // at ρ = 20 a and 40 a it falls fourfold, and it stays below 2 (a/ρ)² (measured ≈ 1.05).
    for (const Vec3& direction : {Vec3(1, 0.5, 1), Vec3(-0.3, 1, 0.6), Vec3(0.2, 0, 1)}) {
        double previous[2] = {0, 0};
        for (const double distance : {20.0, 40.0}) {
            const Vec3 point = distance * direction.normalized();
            const Mat3 normalPoint = boussinesqStress(load, point, nu);
            const Mat3 tangentialPoint = cerrutiStress(load, point, nu);
            const double errors[2] = {
                (hertzNormalStress(load, radius, point, nu) - normalPoint).norm() /
                    normalPoint.norm(),
                (hertzTangentialStress(load, radius, point, nu) - tangentialPoint).norm() /
                    tangentialPoint.norm()};
            for (int k = 0; k < 2; ++k) {
                EXPECT_LT(errors[k], 2 / (distance * distance)) << "load " << k;
                if (previous[k] > 0) {
                    EXPECT_NEAR(previous[k] / errors[k], 4.0, 0.4);
                }
                previous[k] = errors[k];
            }
        }
    }
    // contactStress switches to the point loads beyond farFieldRadii, continuously to that error.
    const HertzLoad both{load, 0.5 * load, radius};
    const Vec3 edge = farFieldRadii * Vec3(0.6, 0, 0.8);
    const Mat3 jump = contactStress(both, edge * (1 + 1e-9), nu) - contactStress(both, edge, nu);
    EXPECT_LT(jump.norm(),
              1 / (farFieldRadii * farFieldRadii) * contactStress(both, edge, nu).norm());
}

TEST(HalfSpaceStress, CircleQuadratureOfPointLoadsReproducesHamiltonBeyondAQuarterRadius) {
    for (const Vec3& point : {Vec3(0, 0, 0.25), Vec3(0.5, 0.3, 0.25), Vec3(1.1, 0, 0.4),
                              Vec3(0.3, -0.8, 0.48), Vec3(2, 1, 1)}) {
        const Mat3 superposed = overHertzCircle(load, radius, point, [](double p, const Vec3& x) {
            return boussinesqStress(p, x, nu);
        });
        const Mat3 closed = hertzNormalStress(load, radius, point, nu);
        EXPECT_LT((superposed - closed).cwiseAbs().maxCoeff(), 1e-3 * p0)
            << "at " << point.transpose();
    }
}

} // namespace
} // namespace slides
