#include "slides/physics/history_integrator.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

namespace slides {

namespace {

constexpr double rootPi = 1.7724538509055160273; // √π

/// g_m(x) = Σ_{k≥m} (−x)^(k−m) / Γ(1 + k/2), m = 0, 1, 2: e^{x²}erfc(x) = g_0 and the two
/// remainders g_0 = 1 − x g_1, g_1 = 2/√π − x g_2 that the start-mode integrals need.
std::array<double, 3> erfcSeriesRemainders(double x) {
    if (x >= 0.5) {
        const double g0 = scaledComplementaryError(x);
        const double g1 = (1.0 - g0) / x;
        return {g0, g1, (2.0 / rootPi - g1) / x};
    }
    // Power series: terms fall by ≥ 2 per order for x < 0.5; 40 terms reach round-off.
    constexpr std::size_t terms = 40;
    static const auto inverseGamma = [] {
        std::array<double, terms + 2> table{};
        for (std::size_t k = 0; k < table.size(); ++k)
            table[k] = 1.0 / std::tgamma(1.0 + 0.5 * static_cast<double>(k));
        return table;
    }();
    std::array<double, 3> g{};
    for (std::size_t m = 0; m < 3; ++m) {
        double power = 1, sum = 0;
        for (std::size_t k = m; k < m + terms; ++k) {
            sum += power * inverseGamma[k];
            power *= -x;
        }
        g[m] = sum;
    }
    return g;
}

/// ∫_p^{p+1} u^(−½) du and ∫_p^{p+1} u^(½) du, in forms without cancellation for large p.
double unitKernelIntegral(double p) { return 2.0 / (std::sqrt(p + 1) + std::sqrt(p)); }
double unitFirstMoment(double p) {
    return (2.0 / 3.0) * (3 * p * p + 3 * p + 1) / (std::pow(p + 1, 1.5) + std::pow(p, 1.5));
}
/// Weights of the older and newer end of the interval p … p+1 steps back, ρ linear on it.
double olderEndWeight(double p) { return unitFirstMoment(p) - p * unitKernelIntegral(p); }
double newerEndWeight(double p) { return (p + 1) * unitKernelIntegral(p) - unitFirstMoment(p); }

} // namespace

double scaledComplementaryError(double x) {
    if (x < 25.0) return std::exp(x * x) * std::erfc(x);
    // Asymptotic series (Abramowitz & Stegun 7.1.23), truncation error < 1e-12 for x ≥ 25.
    const double y = 1.0 / (2.0 * x * x);
    return (1.0 - y * (1.0 - 3.0 * y * (1.0 - 5.0 * y * (1.0 - 7.0 * y)))) / (x * rootPi);
}

StartMode startMode(double alpha, double age) {
    const double rootAge = std::sqrt(age);
    const auto g = erfcSeriesRemainders(alpha * rootAge);
    return {g[0], age * g[2], rootPi * rootAge * g[1]};
}

double productWeight(int order, long lag) {
    const auto k = static_cast<double>(lag);
    if (order == 1) return unitKernelIntegral(k); // ρ constant = its right-end value
    return lag == 0 ? newerEndWeight(0) : olderEndWeight(k - 1) + newerEndWeight(k);
}

double productEndWeight(int order, long lag) {
    return order == 1 ? 0.0 : olderEndWeight(static_cast<double>(lag - 1));
}

ExponentialSum ExponentialSum::fit(double window, double horizon, double accuracy) {
    // Three error sources, each held to accuracy/3 relative to 1/√ℓ on [window, horizon]:
    //  - trapezoid step Δy: aliasing error 2√2 e^{−π²/Δy} (the integrand is analytic in the
    //    strip |Im y| < π/2);
    //  - nodes beyond x_max = X/window: relative error erfc(√(X)) for ℓ ≥ window;
    //  - nodes below x_min: relative error erf(√(x_min ℓ)) ≈ 2√(x_min ℓ/π) for ℓ ≤ horizon.
    const double part = accuracy / 3.0;
    const double stepY =
        std::numbers::pi * std::numbers::pi / std::log(2.0 * std::sqrt(2.0) / part);
    double upper = 1.0;
    while (std::erfc(std::sqrt(upper)) > part) upper *= 1.1;
    const double xMax = upper / window;
    const double xMin = std::pow(part * rootPi / 2.0, 2) / std::max(horizon, window);
    const auto count = static_cast<std::size_t>(std::ceil(std::log(xMax / xMin) / stepY)) + 1;
    ExponentialSum sum;
    for (std::size_t i = 0; i < count; ++i) {
        const double y = std::log(xMin) + static_cast<double>(i) * stepY;
        sum.amplitude.push_back(stepY * std::exp(0.5 * y) / rootPi);
        sum.timescale.push_back(std::exp(-y));
    }
    return sum;
}

double ExponentialSum::operator()(double lag) const {
    double value = 0;
    for (std::size_t i = 0; i < size(); ++i) value += amplitude[i] * std::exp(-lag / timescale[i]);
    return value;
}

FullHistory::FullHistory(double h, int order, const Vec3& startRemainder)
    : rootH_(std::sqrt(h)), order_(order), values_{startRemainder} {}

Vec3 FullHistory::beginStep() {
    const long n = static_cast<long>(values_.size()) - 1; // values ρ_0 … ρ_n
    while (static_cast<long>(weights_.size()) <= n) {
        weights_.push_back(productWeight(order_, static_cast<long>(weights_.size())));
    }
    Vec3 sum = productEndWeight(order_, n + 1) * values_[0];
    for (long j = 1; j <= n; ++j)
        sum += weights_[static_cast<std::size_t>(n + 1 - j)] * values_[static_cast<std::size_t>(j)];
    return rootH_ * sum;
}

WindowTailLayout WindowTailLayout::make(double h, double horizon, double accuracy) {
    WindowTailLayout layout;
    layout.h = h;
    // The tail integrates ρ piecewise linear against each exponential exactly, so the window
    // only has to cover lags where the sum cannot follow the 1/√ℓ singularity. One more window
    // step costs one node; one more term of the sum covers Δy of ln ℓ: the total is least for a
    // window of about 1/Δy steps.
    const double stepY =
        std::numbers::pi * std::numbers::pi / std::log(2.0 * std::sqrt(2.0) / (accuracy / 3.0));
    layout.window = std::max(1, static_cast<int>(std::lround(1.0 / stepY)));
    const double windowLength = layout.window * h;
    layout.tail = ExponentialSum::fit(windowLength, horizon, accuracy);
    const double rootH = std::sqrt(h);
    for (int k = 0; k < layout.window; ++k)
        layout.windowWeights.push_back(rootH * productWeight(2, k));
    layout.windowWeights.push_back(rootH * productEndWeight(2, layout.window));
    for (std::size_t i = 0; i < layout.tail.size(); ++i) {
        // ∫ over the interval entering the tail, lags windowLength … windowLength + h, of ρ
        // linear (newer end at the shorter lag) times a e^{−ℓ/θ}: P − Q on the newer, Q on the
        // older value, P = θ(1 − e^{−z}), Q = θ(1 − e^{−z}(1 + z))/z, z = h/θ.
        const double theta = layout.tail.timescale[i];
        const double z = h / theta;
        const double p = -theta * std::expm1(-z);
        const double q = theta * (z < 1e-4 ? z / 2 - z * z / 3 + z * z * z / 8
                                           : (-std::expm1(-z) - z * std::exp(-z)) / z);
        const double scale = layout.tail.amplitude[i] * std::exp(-windowLength / theta);
        layout.tailDecay.push_back(std::exp(-z));
        layout.tailNewWeight.push_back(scale * (p - q));
        layout.tailOldWeight.push_back(scale * q);
    }
    return layout;
}

Vec3 WindowTailHistory::beginStep() {
    // State: ρ at lags 0 … window, then the tail sums a_i F_i (amplitude folded in).
    const int window = layout_.window;
    const Vec3 leavingNewer = lagged(window - 1);
    const Vec3 leavingOlder = lagged(window);
    Vec3 known = layout_.windowWeights[static_cast<std::size_t>(window)] * leavingNewer;
    for (int k = 1; k < window; ++k)
        known += layout_.windowWeights[static_cast<std::size_t>(k)] * lagged(k - 1);
    double* tail = state_ + 3 * (window + 1);
    for (std::size_t i = 0; i < layout_.tail.size(); ++i) {
        Eigen::Map<Vec3> term(tail + 3 * i);
        term = layout_.tailDecay[i] * term + layout_.tailNewWeight[i] * leavingNewer +
               layout_.tailOldWeight[i] * leavingOlder;
        known += term;
    }
    return known;
}

void WindowTailHistory::endStep(const Vec3& remainder) {
    std::memmove(state_ + 3, state_, sizeof(double) * 3 * static_cast<std::size_t>(layout_.window));
    Eigen::Map<Vec3> newest(state_);
    newest = remainder;
}

StartModeStep startModeStep(double historyRate, const HistoryStart& start, double h) {
    if (start.startSlip.isZero(0)) return {};
    const double alpha = rootPi * historyRate;
    return {startMode(alpha, start.age), startMode(alpha, start.age + h)};
}

template <typename Memory>
StepResult advanceWithHistory(const SlipStep& step, const Vec3& velocity, HistoryStart& start,
                              Memory& memory) {
    return advanceWithHistory(step, velocity, start, memory,
                              startModeStep(step.historyRate, start, step.h));
}

template <typename Memory>
StepResult advanceWithHistory(const SlipStep& step, const Vec3& velocity, HistoryStart& start,
                              Memory& memory, const StartModeStep& modes) {
    const double h = step.h;
    const double theta = step.implicitness;
    const Vec3& s0 = start.startSlip;
    // The start mode s0 φ, integrated in closed form (zero when s0 = 0).
    const StartMode& before = modes.before;
    const StartMode& after = modes.after;
    const Vec3 startIntegral = (after.integral - before.integral) * s0;
    const Vec3 startHistory = (after.history - before.history) * s0;
    const Vec3 remainderBefore = step.gasStart - velocity - before.value * s0;
    const Vec3 known = memory.beginStep();
    const double newestWeight = memory.newestWeight();
    // v_{n+1} = u_{n+1} − s0 φ_{n+1} − ρ_{n+1}, and ρ_{n+1} is the one unknown of
    //   v_{n+1} = v_n + (1/τ)[s0 ΔΦ + h((1−θ)ρ_n + θρ_{n+1})] + h((1−θ)a_n + θa_{n+1})
    //             + r_H [s0 ΔI_φ + √h c_0 ρ_{n+1} + known − I_n].
    const Vec3 rhs = step.gasEnd - after.value * s0 - velocity -
                     step.dragRate * (startIntegral + h * (1 - theta) * remainderBefore) -
                     h * ((1 - theta) * step.forceStart + theta * step.forceEnd) -
                     step.historyRate * (startHistory + known - start.integral);
    const double diagonal = 1 + theta * h * step.dragRate + step.historyRate * newestWeight;
    const Vec3 remainder = rhs / diagonal;
    memory.endStep(remainder);
    start.integral = newestWeight * remainder + known;
    start.age += h;
    const Vec3 newVelocity = step.gasEnd - after.value * s0 - remainder;
    // ∫ v dt = ∫ (v + s0 φ) dt − s0 ∫ φ dt, the first smooth, so the trapezoid keeps its order.
    const Vec3 displacement = h * ((1 - theta) * (velocity + before.value * s0) +
                                   theta * (newVelocity + after.value * s0)) -
                              startIntegral;
    return {newVelocity, displacement};
}

template StepResult advanceWithHistory(const SlipStep&, const Vec3&, HistoryStart&, FullHistory&);
template StepResult advanceWithHistory(const SlipStep&, const Vec3&, HistoryStart&,
                                       WindowTailHistory&);
template StepResult advanceWithHistory(const SlipStep&, const Vec3&, HistoryStart&,
                                       WindowTailHistory&, const StartModeStep&);
template StepResult advanceWithHistory(const SlipStep&, const Vec3&, HistoryStart&, NoHistory&);

} // namespace slides
