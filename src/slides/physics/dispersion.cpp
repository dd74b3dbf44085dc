#include "slides/physics/dispersion.h"

#include "slides/core/random.h"

#include <algorithm>
#include <limits>

namespace slides {

namespace {

/// A step longer than this many T_L after an eddy ended is finished in one Gaussian piece.
constexpr double eddiesWalkedPerStep = 50.0;

bool isTurbulent(double k, double epsilon) { return k > 0 && epsilon > 0; }

/// A non-finite k or ε gives a non-finite fluctuation, which the stepper reports as an error
/// naming the particle, instead of passing for laminar gas.
bool isBroken(double k, double epsilon) { return !std::isfinite(k) || !std::isfinite(epsilon); }

const Vec3 broken = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());

Vec3 standardNormalVector(RandomStream& random) {
    const double x = random.normal();
    const double y = random.normal();
    return {x, y, random.normal()};
}

/// Path of the particle relative to the eddy gas over t, for the relative velocity w at the
/// start, drift w_∞ = τa and response time τ: Δ(t) = w_∞ t + (w − w_∞) τ (1 − e^(−t/τ)).
Vec3 relativePath(const Vec3& relative, const Vec3& drift, double tau, double t) {
    return drift * t + (relative - drift) * (-tau * std::expm1(-t / tau));
}

/// The time in (0, t] at which |Δ| reaches length, given |Δ(t)| > length: Newton's method on
/// |Δ(s)| − length, d|Δ|/ds = Δ·Δ'/|Δ| with Δ' = w_∞ + (w − w_∞) e^(−s/τ), from the secant
/// guess s = t·length/|Δ(t)| (|Δ(0)| = 0), kept inside the bracket where |Δ| − length changes
/// sign (bisecting where a step would leave it) until a step is below 1e-14 t: a few iterations
/// where bisection took forty.
double crossingTime(const Vec3& relative, const Vec3& drift, double tau, double t, double length) {
    double low = 0, high = t;
    double s = t * length / relativePath(relative, drift, tau, t).norm();
    for (int iteration = 0; iteration < 100; ++iteration) {
        const Vec3 path = relativePath(relative, drift, tau, s);
        const double distance = path.norm();
        const double excess = distance - length;
        (excess < 0 ? low : high) = s;
        const Vec3 velocity = drift + (relative - drift) * std::exp(-s / tau);
        double next = s - excess * distance / path.dot(velocity);
        if (!(next > low && next < high)) next = 0.5 * (low + high);
        if (std::abs(next - s) <= 1e-14 * t) return next;
        s = next;
    }
    return high;
}

/// f(a) = 2a − 3 + 4e^(−a) − e^(−2a): Var(∫ξ dt over a T_L) = T_L² f(a) for the
/// exponentially correlated ξ started at a known value. Series below a = 0.1 (the closed form
/// cancels), next term 127 a⁹/90720 < 2e-9 f(a).
double integratedVarianceFactor(double a) {
    if (a < 0.1)
        return a * a * a *
               (2.0 / 3.0 + a * (-0.5 + a * (7.0 / 30.0 +
                                             a * (-1.0 / 12.0 + a * (31.0 / 1260.0 - a / 160.0)))));
    const double m = std::expm1(-a); // e^(−a) − 1
    return 2.0 * a + 2.0 * m - m * m;
}

} // namespace

void drawEddy(EddyState& state, double lagrangianTime, double eddyLength, RandomKey key) {
    RandomStream random(key.seed, key.particleId, RandomPurpose::eddy, state.count++);
    state.standardised = standardNormalVector(random);
    state.timeLeft = -lagrangianTime * std::log(random.uniform()); // Exp(mean T_L)
    state.lengthLeft = eddyLength;
}

Vec3 eddyInteractionStep(EddyState& state, const DispersionConstants& constants, double k,
                         double epsilon, const ParticleResponse& particle, double h,
                         RandomKey key) {
    if (isBroken(k, epsilon)) return broken;
    if (!isTurbulent(k, epsilon) || !(h > 0)) {
        state.timeLeft = 0; // laminar here: the eddy ends
        return Vec3::Zero();
    }
    const double sigma = fluctuationRms(k);
    const double lagrangianTime = lagrangianTimeScale(constants, k, epsilon);
    const double eddyLength = eddyLengthScale(constants, k, epsilon);
    const double tau = particle.responseTime;
    const Vec3 drift = tau * particle.bodyAcceleration;
    Vec3 relative = particle.slip - sigma * state.standardised; // v − (U + u')
    Vec3 integral = Vec3::Zero();                               // ∫ξ dt over the step
    double remaining = h;
    while (remaining > 0) {
        if (state.timeLeft <= 0 || state.lengthLeft <= 0) {
            if (remaining > eddiesWalkedPerStep * lagrangianTime) {
                // Many eddies left in this step: their ∫ξ dt in one draw (exact variance).
                RandomStream random(key.seed, key.particleId, RandomPurpose::eddy, state.count++);
                // Stationary start: Var(∫ξ dt over a T_L) = 2 T_L² (a − 1 + e^(−a)).
                const double a = remaining / lagrangianTime;
                const double spread = lagrangianTime * std::sqrt(2.0 * (a + std::expm1(-a)));
                integral += spread * standardNormalVector(random);
                state.timeLeft = 0;
                break;
            }
            const Vec3 previous = state.standardised;
            drawEddy(state, lagrangianTime, eddyLength, key);
            relative += sigma * (previous - state.standardised);
        }
        double piece = std::min(remaining, state.timeLeft);
        bool crossed = false;
        if (relativePath(relative, drift, tau, piece).norm() >= state.lengthLeft) {
            piece = crossingTime(relative, drift, tau, piece, state.lengthLeft);
            crossed = true;
        }
        integral += state.standardised * piece;
        state.lengthLeft -= relativePath(relative, drift, tau, piece).norm();
        relative = drift + (relative - drift) * std::exp(-piece / tau);
        state.timeLeft -= piece;
        if (crossed) state.lengthLeft = 0;
        remaining = piece < remaining ? remaining - piece : 0.0;
    }
    return (sigma / h) * integral;
}

Vec3 langevinStep(EddyState& state, const DispersionConstants& constants, double k, double epsilon,
                  double h, RandomKey key) {
    if (isBroken(k, epsilon)) return broken;
    if (!isTurbulent(k, epsilon) || !(h > 0)) return Vec3::Zero();
    const double lagrangianTime = lagrangianTimeScale(constants, k, epsilon);
    RandomStream random(key.seed, key.particleId, RandomPurpose::eddy, state.count++);
    if (state.count == 1) state.standardised = standardNormalVector(random); // stationary start
    // Exact joint update of ξ(h) and X = ∫ξ dt (Gillespie 1996), a = h/T_L, m = e^(−a) − 1:
    //   ξ(h) = e^(−a) ξ0 + √(1 − e^(−2a)) n1,
    //   X = T_L (1 − e^(−a)) ξ0 + [Cov/Var ξ] (ξ(h) − e^(−a) ξ0) + √(Var X − Cov²/Var ξ) n2,
    //   Var ξ = 1 − e^(−2a), Cov = T_L (1 − e^(−a))², Var X = T_L² f(a).
    const double a = h / lagrangianTime;
    const double m = std::expm1(-a);
    const double decay = 1.0 + m;
    const double endVariance = -m * (2.0 + m);
    const double covariance = lagrangianTime * m * m;
    const double conditional =
        std::max(0.0, lagrangianTime * lagrangianTime * integratedVarianceFactor(a) -
                          covariance * covariance / endVariance);
    const Vec3 start = state.standardised;
    const Vec3 innovation = std::sqrt(endVariance) * standardNormalVector(random);
    const Vec3 integral = (-lagrangianTime * m) * start + (covariance / endVariance) * innovation +
                          std::sqrt(conditional) * standardNormalVector(random);
    state.standardised = decay * start + innovation;
    return (fluctuationRms(k) / h) * integral;
}

} // namespace slides
