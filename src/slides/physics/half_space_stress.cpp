#include "slides/physics/half_space_stress.h"

#include <boost/math/quadrature/gauss.hpp>

#include <array>
#include <cmath>
#include <numbers>

namespace slides {

namespace {

Mat3 symmetric(double xx, double yy, double zz, double xy, double xz, double yz) {
    Mat3 stress;
    stress << xx, xy, xz, xy, yy, yz, xz, yz, zz;
    return stress;
}

/// Below this distance from the axis, in contact radii, the Hertz field takes its axis values:
/// Hamilton's 1/r⁴ terms cancel there (rounding ~ 1e-16/(r/a)², the axis values' error (r/a)²).
constexpr double axisRadii = 1e-4;

/// Points across the circle of Cerruti's superposition (hertzCircle).
constexpr int radialPoints = 16;
constexpr int angularPoints = 48;

} // namespace

/// ∫∫ q dA over the unit circle with q ∝ √(1 − s²): with u = √(1 − s²), s ds = −u du, the
/// radial integral ∫₀¹ f(s) √(1 − s²) s ds becomes ∫₀¹ f(√(1 − u²)) u² du = 1/3 for f = 1.
std::span<const CirclePoint> hertzCircle() {
    static const auto points = [] {
        using Rule = boost::math::quadrature::gauss<double, radialPoints>;
        std::array<CirclePoint, radialPoints * angularPoints> circle{};
        std::size_t k = 0;
        for (std::size_t n = 0; n < Rule::abscissa().size(); ++n) {
            for (const double side : {-1.0, 1.0}) {
                const double u = 0.5 * (1 + side * Rule::abscissa()[n]);
                const double radialWeight = 0.5 * Rule::weights()[n] * u * u;
                const double s = std::sqrt(1 - u * u);
                for (int j = 0; j < angularPoints; ++j) {
                    const double angle = 2 * std::numbers::pi * (j + 0.5) / angularPoints;
                    circle[k++] = {s * std::cos(angle), s * std::sin(angle),
                                   3 * radialWeight / angularPoints};
                }
            }
        }
        return circle;
    }();
    return points;
}

Mat3 boussinesqStress(double normalLoad, const Vec3& point, double poisson) {
    const double x = point.x(), y = point.y(), z = point.z();
    const double r2 = x * x + y * y;
    const double rho = point.norm();
    const double rho3 = rho * rho * rho, rho5 = rho3 * rho * rho;
    const double k = normalLoad / (2 * std::numbers::pi);
    const double c = 1 - 2 * poisson;
    // (1 − z/ρ)/r², finite on the axis (→ 1/(2z²)).
    const double rim = r2 > 1e-12 * rho * rho ? (1 - z / rho) / r2 : 1 / (2 * z * z);
    const double surfaceX = r2 > 0 ? x * x / r2 : 0.5, surfaceY = r2 > 0 ? y * y / r2 : 0.5;
    const double xy = r2 > 0 ? x * y / r2 : 0.0;
    return k * symmetric(
                   c * (rim * (surfaceX - surfaceY) + z / rho3 * surfaceY) - 3 * z * x * x / rho5,
                   c * (rim * (surfaceY - surfaceX) + z / rho3 * surfaceX) - 3 * z * y * y / rho5,
                   -3 * z * z * z / rho5, c * (2 * rim * xy - z / rho3 * xy) - 3 * x * y * z / rho5,
                   -3 * x * z * z / rho5, -3 * y * z * z / rho5);
}

Mat3 cerrutiStress(double tangentialLoad, const Vec3& point, double poisson) {
    const double x = point.x(), y = point.y(), z = point.z();
    const double rho = point.norm();
    const double rho2 = rho * rho, rho3 = rho2 * rho, rho5 = rho3 * rho2;
    const double sum = rho + z, sum2 = sum * sum, sum3 = sum2 * sum;
    const double k = tangentialLoad / (2 * std::numbers::pi);
    const double c = 1 - 2 * poisson;
    return k *
           symmetric(-3 * x * x * x / rho5 +
                         c * (x / rho3 - 3 * x / (rho * sum2) + x * x * x / (rho3 * sum2) +
                              2 * x * x * x / (rho2 * sum3)),
                     -3 * x * y * y / rho5 +
                         c * (x / rho3 - x / (rho * sum2) + x * y * y / (rho3 * sum2) +
                              2 * x * y * y / (rho2 * sum3)),
                     -3 * x * z * z / rho5,
                     -3 * x * x * y / rho5 + c * (-y / (rho * sum2) + x * x * y / (rho3 * sum2) +
                                                  2 * x * x * y / (rho2 * sum3)),
                     -3 * x * x * z / rho5, -3 * x * y * z / rho5);
}

Mat3 hertzNormalStress(double normalLoad, double contactRadius, const Vec3& point, double poisson) {
    const double a = contactRadius, nu = poisson;
    const double x = point.x(), y = point.y(), z = point.z();
    const double r2 = x * x + y * y;
    const double k = 3 * normalLoad / (2 * std::numbers::pi * a * a * a);
    if (r2 < axisRadii * axisRadii * a * a) { // Johnson Eq. 3.44–3.45 (the axis)
        const double lateral =
            k * ((1 + nu) * (z * std::atan(a / z) - a) + a * a * a / (2 * (a * a + z * z)));
        return symmetric(lateral, lateral, -k * a * a * a / (a * a + z * z), 0, 0, 0);
    }
    // Hamilton (1983): A, S, M, N, φ, G, H of his Eq. 6–10.
    const double A = r2 + z * z - a * a;
    const double S = std::sqrt(A * A + 4 * a * a * z * z);
    const double M = std::sqrt(0.5 * (S + A)), N = std::sqrt(0.5 * (S - A));
    const double phi = std::atan(a / M);
    const double G = M * M - N * N + z * M - a * N, H = 2 * M * N + a * M + z * N;
    const double r4 = r2 * r2;
    const double bracket =
        (1 - nu) * N * z * z - (1 - 2 * nu) / 3 * (N * S + 2 * A * N + a * a * a) - nu * M * z * a;
    const auto lateral = [&](double along, double across) {
        return k * ((1 + nu) * z * phi + ((across * across - along * along) / r2 * bracket -
                                          N * (along * along + 2 * nu * across * across) -
                                          M * along * along * z * a / S) /
                                             r2);
    };
    const double shearXY = k * x * y / r4 *
                           ((1 - 2 * nu) * (-N * r2 + 2.0 / 3 * N * (S + 2 * A) -
                                            z * (z * N + a * M) + 2.0 / 3 * a * a * a) +
                            z * (-a * M * r2 / S - z * N + a * M));
    const double depthShear = N / S - z * H / (G * G + H * H);
    return symmetric(lateral(x, y), lateral(y, x), k * (-N + a * z * M / S), shearXY,
                     -k * z * x * depthShear, -k * z * y * depthShear);
}

Mat3 hertzTangentialStress(double tangentialLoad, double contactRadius, const Vec3& point,
                           double poisson) {
    return overHertzCircle(
        tangentialLoad, contactRadius, point,
        [poisson](double load, const Vec3& at) { return cerrutiStress(load, at, poisson); });
}

Mat3 contactStress(const HertzLoad& load, const Vec3& point, double poisson) {
    if (point.squaredNorm() > farFieldRadii * farFieldRadii * load.radius * load.radius)
        return boussinesqStress(load.normal, point, poisson) +
               cerrutiStress(load.tangential, point, poisson);
    Mat3 stress = hertzNormalStress(load.normal, load.radius, point, poisson);
    if (load.tangential != 0)
        stress += hertzTangentialStress(load.tangential, load.radius, point, poisson);
    return stress;
}

} // namespace slides
