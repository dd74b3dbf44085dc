#include "slides/physics/finite_reynolds_kernel.h"

#include "slides/physics/particle_reynolds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <numbers>

namespace slides {

namespace {

// The grid of t = ln y for q and w, and of ln X for κ.
constexpr double tMin = -40, tMax = 40, tStep = 0.05;
// Below e^{−15} the two halves of κ's integral (each ∝ √X) cancel to its X^(3/2): there
// the power law, whose next term is X^p relative.
constexpr double kappaMin = -15, kappaMax = 35, kappaStep = 0.1;
constexpr int nodeCount(double lo, double hi, double step) {
    return static_cast<int>((hi - lo) / step + 0.5) + 1;
}

// 8-point Gauss–Legendre on [−1, 1], by symmetry.
constexpr std::array<double, 4> glNode{0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                       0.9602898564975363};
constexpr std::array<double, 4> glWeight{0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                         0.1012285362903763};
template <typename Function> double gaussLegendre(double a, double b, const Function& f) {
    const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
    double sum = 0;
    for (std::size_t i = 0; i < glNode.size(); ++i)
        sum += glWeight[i] * (f(mid - half * glNode[i]) + f(mid + half * glNode[i]));
    return half * sum;
}

/// Quintic Hermite interpolation at t of values f with t-derivatives d1, d2 on the grid.
double quinticHermite(const std::vector<double>& f, const std::vector<double>& d1,
                      const std::vector<double>& d2, double t) {
    const double position = (t - tMin) / tStep;
    const auto k = std::min(static_cast<std::size_t>(position), f.size() - 2);
    const double u = position - static_cast<double>(k);
    const double u2 = u * u, u3 = u2 * u, u4 = u3 * u, u5 = u4 * u;
    const double h0 = 1 - 10 * u3 + 15 * u4 - 6 * u5, h1 = u - 6 * u3 + 8 * u4 - 3 * u5;
    const double h2 = 0.5 * (u2 - 3 * u3 + 3 * u4 - u5), h3 = 10 * u3 - 15 * u4 + 6 * u5;
    const double h4 = -4 * u3 + 7 * u4 - 3 * u5, h5 = 0.5 * (u3 - 2 * u4 + u5);
    return f[k] * h0 + tStep * d1[k] * h1 + tStep * tStep * d2[k] * h2 + f[k + 1] * h3 +
           tStep * d1[k + 1] * h4 + tStep * tStep * d2[k + 1] * h5;
}

} // namespace

double crossoverLag(const FiniteReynoldsShape& shape, double slipSpeed, double particleRadius,
                    double kinematicViscosity, double accelerationFactor) {
    if (slipSpeed == 0) return std::numeric_limits<double>::infinity();
    const double reynolds = particleReynolds(slipSpeed, particleRadius, kinematicViscosity);
    const double fH = 0.75 + shape.fHSlope * reynolds;
    return std::cbrt(4.0 / std::numbers::pi) * kinematicViscosity * fH * fH /
           (slipSpeed * slipSpeed) * std::pow(accelerationFactor, -1.0 / shape.power());
}

const FiniteReynoldsKernel& FiniteReynoldsKernel::of(const FiniteReynoldsShape& shape) {
    static std::mutex guard;
    static std::map<std::pair<double, double>, FiniteReynoldsKernel> built;
    const std::lock_guard lock(guard);
    const auto key = std::pair{shape.exponent, shape.fHSlope};
    auto found = built.find(key);
    if (found == built.end()) found = built.emplace(key, FiniteReynoldsKernel(shape)).first;
    return found->second;
}

double FiniteReynoldsKernel::shapeFunction(double y) const {
    return std::exp(-shape_.exponent * std::log1p(std::pow(y, shape_.power())));
}

FiniteReynoldsKernel::FiniteReynoldsKernel(const FiniteReynoldsShape& shape) : shape_(shape) {
    const double c1 = shape.exponent, p = shape.power();
    // q = ∫_0^y u^(−½)F and r = ∫_0^y u^(½)F, so w = y q − r; from the series F ≈ 1 − c1 y^p
    // below the grid, then panel by panel in t (smooth integrands e^{t/2}F, e^{3t/2}F).
    const auto qIntegrand = [&](double t) {
        return std::exp(0.5 * t) * shapeFunction(std::exp(t));
    };
    const auto rIntegrand = [&](double t) {
        return std::exp(1.5 * t) * shapeFunction(std::exp(t));
    };
    double y = std::exp(tMin);
    double q = 2 * std::sqrt(y) - c1 * std::pow(y, p + 0.5) / (p + 0.5);
    double r = (2.0 / 3.0) * std::pow(y, 1.5) - c1 * std::pow(y, p + 1.5) / (p + 1.5);
    const int count = nodeCount(tMin, tMax, tStep);
    for (int k = 0; k < count; ++k) {
        const double t = tMin + k * tStep;
        if (k > 0) {
            q += gaussLegendre(t - tStep, t, qIntegrand);
            r += gaussLegendre(t - tStep, t, rIntegrand);
        }
        y = std::exp(t);
        const double f = shapeFunction(y), rootY = std::sqrt(y);
        const double yFPrime = -c1 * p * std::pow(y, p) / (1 + std::pow(y, p)) * f; // y F'(y)
        const double qT = rootY * f, qTT = 0.5 * rootY * f + rootY * yFPrime;
        const double w = y * q - r, wT = y * q, wTT = y * q + y * rootY * f;
        logQ_.push_back(std::log(q));
        logQ1_.push_back(qT / q);
        logQ2_.push_back(qTT / q - (qT / q) * (qT / q));
        logW_.push_back(std::log(w));
        logW1_.push_back(wT / w);
        logW2_.push_back(wTT / w - (wT / w) * (wT / w));
    }
    // Beyond the grid F ≈ y^(−3/2)(1 − c1 y^(−p)): q = q∞ − 1/y + c1 y^(−1−p)/(1 + p).
    qInfinity_ = q + 1 / y - c1 * std::pow(y, -1 - p) / (1 + p);
    rAtEnd_ = r;

    // κ(X): the part ρ < 1 in t = ln ρ (the integrand's singularities lie π(1 − p)/p off the
    // real t axis), from where F = 1 and e^{−ρ} = 1 to 1e-13 (the part below in closed form,
    // 2√ρ), the rest
    // in ρ up to 45 (e^{−45} negligible); Re(1 + a e^{−iπp})^(−c1) = |z|^(−c1) cos(c1 arg z).
    const double cosine = std::cos(std::numbers::pi * p), sine = std::sin(std::numbers::pi * p);
    const auto realShape = [&](double ratio) {
        const double a = std::pow(ratio, p);
        const double re = 1 + a * cosine, im = -a * sine;
        return std::pow(std::hypot(re, im), -c1) * std::cos(c1 * std::atan2(im, re));
    };
    const int kappaCount = nodeCount(kappaMin, kappaMax, kappaStep);
    for (int k = 0; k < kappaCount; ++k) {
        const double logX = kappaMin + k * kappaStep, x = std::exp(logX);
        const double start = std::min(logX, 0.0) - 40.0;
        double sum = 2 * std::exp(0.5 * start);
        const auto inLog = [&](double t) {
            const double rho = std::exp(t);
            return std::exp(0.5 * t - rho) * realShape(rho / x);
        };
        const auto inRho = [&](double rho) {
            return std::exp(-rho) / std::sqrt(rho) * realShape(rho / x);
        };
        const int logPanels = static_cast<int>(std::ceil(-start));
        for (int i = 0; i < logPanels; ++i) {
            const double a = start + i * (-start / logPanels);
            sum += gaussLegendre(a, a - start / logPanels, inLog);
        }
        for (double rho = 1; rho < 45; rho += 0.5) sum += gaussLegendre(rho, rho + 0.5, inRho);
        logKappa_.push_back(std::log(sum / std::sqrt(std::numbers::pi)));
    }
}

double FiniteReynoldsKernel::q(double y) const {
    if (y == 0) return 0;
    const double t = std::log(y), c1 = shape_.exponent, p = shape_.power();
    if (t < tMin) return 2 * std::sqrt(y) - c1 * std::pow(y, p + 0.5) / (p + 0.5);
    if (t > tMax) return qInfinity_ - 1 / y + c1 * std::pow(y, -1 - p) / (1 + p);
    return std::exp(quinticHermite(logQ_, logQ1_, logQ2_, t));
}

double FiniteReynoldsKernel::w(double y) const {
    if (y == 0) return 0;
    const double t = std::log(y), c1 = shape_.exponent, p = shape_.power();
    if (t < tMin)
        return (4.0 / 3.0) * std::pow(y, 1.5) - c1 * std::pow(y, p + 1.5) / ((p + 0.5) * (p + 1.5));
    if (t > tMax) {
        const double yEnd = std::exp(tMax);
        const double r =
            rAtEnd_ + std::log(y / yEnd) + (c1 / p) * (std::pow(y, -p) - std::pow(yEnd, -p));
        return y * q(y) - r;
    }
    return std::exp(quinticHermite(logW_, logW1_, logW2_, t));
}

double FiniteReynoldsKernel::kernel(double lag, double crossover) const {
    return shapeFunction(lag / crossover) / std::sqrt(lag);
}

double FiniteReynoldsKernel::firstIntegral(double lag, double crossover) const {
    if (std::isinf(crossover)) return 2 * std::sqrt(lag);
    return std::sqrt(crossover) * q(lag / crossover);
}

double FiniteReynoldsKernel::secondIntegral(double lag, double crossover) const {
    if (std::isinf(crossover)) return (4.0 / 3.0) * lag * std::sqrt(lag);
    return crossover * std::sqrt(crossover) * w(lag / crossover);
}

double FiniteReynoldsKernel::intervalWeight(double lag, double length, double crossover) const {
    // Far from the lag 0 singularity, Q's mean by 3-point Gauss–Legendre (relative error
    // ~4e-6 (h/ℓ)^6 < 1e-14 beyond ℓ = 32 h); nearer, the difference of W (no cancellation).
    if (lag >= 32 * length) {
        constexpr double node = 0.7745966692414834; // √(3/5)
        const double mid = lag + 0.5 * length, half = 0.5 * length;
        return (5 * firstIntegral(mid - half * node, crossover) +
                8 * firstIntegral(mid, crossover) +
                5 * firstIntegral(mid + half * node, crossover)) /
               18;
    }
    return (secondIntegral(lag + length, crossover) - secondIntegral(lag, crossover)) / length;
}

double FiniteReynoldsKernel::spectrumRatio(double x) const {
    return spectrumRatioAtLog(std::log(x));
}

double FiniteReynoldsKernel::spectrumRatioAtLog(double logX) const {
    if (logX > kappaMax) {
        // F ≈ 1 − c1 (ρ/X)^p e^{−iπp}: κ ≈ 1 − c1 cos(πp) Γ(p + ½)/√π X^(−p) (1 for X = ∞).
        const double p = shape_.power();
        return 1 - shape_.exponent * std::cos(std::numbers::pi * p) * std::tgamma(p + 0.5) /
                       std::sqrt(std::numbers::pi) * std::exp(-p * logX);
    }
    if (logX < kappaMin) return std::exp(logKappa_.front() + 1.5 * (logX - kappaMin)); // K̂ ∝ ℓ^(−2)
    // Cubic Lagrange on the four nearest nodes k … k + 3, at u from node k.
    const double position = (logX - kappaMin) / kappaStep;
    const auto last = static_cast<long>(logKappa_.size()) - 1;
    const long k = std::clamp(static_cast<long>(position) - 1, 0L, last - 3);
    const double u = position - static_cast<double>(k);
    const double* f = logKappa_.data() + k;
    const double value = -(u - 1) * (u - 2) * (u - 3) / 6 * f[0] +
                         u * (u - 2) * (u - 3) / 2 * f[1] - u * (u - 1) * (u - 3) / 2 * f[2] +
                         u * (u - 1) * (u - 2) / 6 * f[3];
    return std::exp(value);
}

} // namespace slides
