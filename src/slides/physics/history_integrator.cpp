#include "slides/physics/history_integrator.h"

#include "slides/physics/finite_reynolds_history.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

namespace slides {

namespace {

constexpr double rootPi = 1.7724538509055160273; // √π

/// g_m(x) = Σ_{k≥m} (−x)^(k−m) / Γ(1 + k/2), m = 0 … orders − 1: e^{x²}erfc(x) = g_0 and the
/// remainders g_m = 1/Γ(1 + m/2) − x g_{m+1} that the start-mode integrals (m ≤ 2) and the spin
/// kernel's weights (m ≤ 4) need.
template <std::size_t orders> std::array<double, orders> erfcSeriesRemainders(double x) {
    constexpr std::size_t chains = 4, longest = 8, terms = chains * longest;
    static const auto inverseGamma = [] {
        std::array<double, terms + orders> table{};
        for (std::size_t k = 0; k < table.size(); ++k)
            table[k] = 1.0 / std::tgamma(1.0 + 0.5 * static_cast<double>(k));
        return table;
    }();
    // reach[s]: the largest x at which s steps of the chains below suffice, their first omitted
    // term x^{4s}/Γ(1 + k/2) (which bounds the rest, alternating and falling) under 1e-17 of the
    // first; 8 steps reach x = 0.84.
    static const auto reach = [] {
        std::array<double, longest + 1> table{};
        for (std::size_t steps = 1; steps <= longest; ++steps)
            table[steps] = std::pow(1e-17 * inverseGamma[orders - 1] /
                                        inverseGamma[orders - 1 + chains * steps],
                                    1.0 / static_cast<double>(chains * steps));
        return table;
    }();
    std::array<double, orders> g{};
    if (x >= 0.5) {
        g[0] = scaledComplementaryError(x);
        for (std::size_t m = 1; m < orders; ++m) g[m] = (inverseGamma[m - 1] - g[m - 1]) / x;
        return g;
    }
    // For x < 0.5: the power series of the last g, then the recursion downwards, which
    // multiplies errors by x. The series as four Horner chains in x⁴, Σ_r (−x)^r Σ_j c_{4j+r}
    // x^{4j}, independent so that they overlap in the pipeline, only as long as x needs (a heavy
    // particle in a gas keeps x = α√age small for long: few steps).
    std::size_t steps = 1;
    while (x > reach[steps]) ++steps;
    const double x2 = x * x, x4 = x2 * x2;
    std::array<double, chains> chain{};
    for (std::size_t j = steps; j-- > 0;)
        for (std::size_t r = 0; r < chains; ++r)
            chain[r] = chain[r] * x4 + inverseGamma[orders - 1 + chains * j + r];
    g[orders - 1] = (chain[0] - x * chain[1]) + x2 * (chain[2] - x * chain[3]);
    for (std::size_t m = orders - 1; m-- > 0;) g[m] = inverseGamma[m] - x * g[m + 1];
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

/// Weights of the newer (lag `lag`) and older (lag + length) node of the spin kernel's bounded
/// part √(π/t_v) ψ(ℓ/t_v), ψ(U) = e^U erfc(√U), on that step with ρ linear on it [√s].
struct EndWeights {
    double newer, older;
};
EndWeights boundedPartWeights(double lag, double length, double viscousTime) {
    const double start = lag / viscousTime, span = length / viscousTime; // in U = ℓ/t_v
    const double scale = std::sqrt(std::numbers::pi * viscousTime);
    if (lag == 0) {
        // ∫_0^U ψ = U g_2 and ∫_0^U u ψ du = U²(1 − g_4 − x g_3), x = √U, without cancellation.
        const double x = std::sqrt(span);
        const auto g = erfcSeriesRemainders<5>(x);
        const double zeroth = span * g[2], first = span * span * (1 - g[4] - x * g[3]);
        const double older = first / span;
        return {scale * (zeroth - older), scale * older};
    }
    // ψ is analytic around the step, which lies at least its length from U = 0: 8-point
    // Gauss–Legendre errs below 1e-12.
    static constexpr std::array<double, 4> node{0.1834346424956498, 0.5255324099163290,
                                                0.7966664774136267, 0.9602898564975363};
    static constexpr std::array<double, 4> weight{0.3626837833783620, 0.3137066458778873,
                                                  0.2223810344533745, 0.1012285362903763};
    EndWeights sum{0, 0};
    for (std::size_t i = 0; i < node.size(); ++i) {
        for (const double side : {-1.0, 1.0}) {
            const double fraction = 0.5 * (1 + side * node[i]); // 0 at the newer end
            const double psi = scaledComplementaryError(std::sqrt(start + fraction * span));
            sum.newer += 0.5 * weight[i] * psi * (1 - fraction);
            sum.older += 0.5 * weight[i] * psi * fraction;
        }
    }
    return {scale * span * sum.newer, scale * span * sum.older};
}

} // namespace

double scaledComplementaryError(double x) {
    if (x < 25.0) return std::exp(x * x) * std::erfc(x);
    // Asymptotic series (Abramowitz & Stegun 7.1.23), truncation error < 1e-12 for x ≥ 25.
    const double y = 1.0 / (2.0 * x * x);
    return (1.0 - y * (1.0 - 3.0 * y * (1.0 - 5.0 * y * (1.0 - 7.0 * y)))) / (x * rootPi);
}

StartMode startMode(double alpha, double age) {
    const double rootAge = std::sqrt(age);
    const auto g = erfcSeriesRemainders<3>(alpha * rootAge);
    return {g[0], age * g[2], rootPi * rootAge * g[1]};
}

StartMode spinStartMode(double historyRate, double viscousTime, double age) {
    // φ̂ = (1 + √(t_v p))/(p (1 + b + √(t_v p))) = [1/p + b √t_v /(1 + b) (1/√p − 1/(√p + c))]
    // /(1 + b): the inverse transforms 1, and c E(c√t) whose integral is t g_2 (as Basset's).
    const double b = historyRate * std::sqrt(std::numbers::pi * viscousTime);
    const double c = (1 + b) / std::sqrt(viscousTime);
    const double rootAge = std::sqrt(age);
    const auto g = erfcSeriesRemainders<3>(c * rootAge);
    return {(1 + b * g[0]) / (1 + b), age * (1 + b * g[2]) / (1 + b), rootPi * rootAge * g[1]};
}

double productWeight(int order, long lag) {
    const auto k = static_cast<double>(lag);
    if (order == 1) return unitKernelIntegral(k); // ρ constant = its right-end value
    return lag == 0 ? newerEndWeight(0) : olderEndWeight(k - 1) + newerEndWeight(k);
}

double productEndWeight(int order, long lag) {
    return order == 1 ? 0.0 : olderEndWeight(static_cast<double>(lag - 1));
}

double kernelWeight(int order, long lag, double h, HistoryKernel kernel) {
    double weight = std::sqrt(h) * productWeight(order, lag);
    if (kernel.viscousTime == 0) return weight;
    // Order 1: ρ constant on the step lag … lag + 1 at its newer value; order 2: linear.
    const auto lagged = static_cast<double>(lag);
    const EndWeights step = boundedPartWeights(lagged * h, h, kernel.viscousTime);
    weight -= step.newer;
    if (order == 1) return weight - step.older;
    if (lag > 0) weight -= boundedPartWeights((lagged - 1) * h, h, kernel.viscousTime).older;
    return weight;
}

double kernelEndWeight(int order, long lag, double h, HistoryKernel kernel) {
    if (order == 1) return 0.0;
    const double weight = std::sqrt(h) * productEndWeight(order, lag);
    if (kernel.viscousTime == 0) return weight;
    return weight -
           boundedPartWeights(static_cast<double>(lag - 1) * h, h, kernel.viscousTime).older;
}

FirstStepWeights firstStepWeights(int order, double lag, double firstStep, HistoryKernel kernel) {
    const double p = lag / firstStep, root = std::sqrt(firstStep);
    FirstStepWeights weights =
        order == 1 ? FirstStepWeights{root * unitKernelIntegral(p), 0.0}
                   : FirstStepWeights{root * newerEndWeight(p), root * olderEndWeight(p)};
    if (kernel.viscousTime == 0) return weights;
    const EndWeights bounded = boundedPartWeights(lag, firstStep, kernel.viscousTime);
    if (order == 1) return {weights.newer - bounded.newer - bounded.older, 0.0};
    return {weights.newer - bounded.newer, weights.older - bounded.older};
}

namespace {

/// The tail's weights for the step entering it, lags windowLength … windowLength + length, of
/// ρ linear (newer end at the shorter lag) times a e^{−ℓ/θ}: P − Q on the newer, Q on the older
/// value, P = θ(1 − e^{−z}), Q = θ(1 − e^{−z}(1 + z))/z, z = length/θ, times e^{−windowLength/θ}.
EndWeights tailEntryWeights(double amplitude, double theta, double windowLength, double length) {
    const double z = length / theta;
    const double p = -theta * std::expm1(-z);
    const double q = theta * (z < 1e-4 ? z / 2 - z * z / 3 + z * z * z / 8
                                       : (-std::expm1(-z) - z * std::exp(-z)) / z);
    const double scale = amplitude * std::exp(-windowLength / theta);
    return {scale * (p - q), scale * q};
}

} // namespace

namespace {

/// The nodes of the trapezoid sum below its lowest one, x_k = x_0 e^{−kΔy} with amplitudes
/// a_0 e^{−kΔy/2} (k ≥ 1), lumped into one term of their total amplitude at their mean rate: for
/// x_0 ℓ small they act as one (the error is second order in x_0 ℓ), so the sum need not reach
/// the rates x ~ accuracy²/horizon that truncating them there would need.
struct LumpedNodes {
    double amplitude, rate;

    LumpedNodes(double lowestAmplitude, double lowestRate, double stepY) {
        const double r = std::exp(-0.5 * stepY), q = std::exp(-stepY);
        amplitude = lowestAmplitude * r / (1 - r);
        rate = lowestRate * q * (1 - r) / (1 - r * q);
    }
    /// Relative error against the nodes it stands for, at lag ℓ (their sum to 1e-17).
    static double error(double lowestAmplitude, double lowestRate, double stepY, double lag) {
        const LumpedNodes lumped(lowestAmplitude, lowestRate, stepY);
        double exact = 0, amplitude = lowestAmplitude, rate = lowestRate;
        for (int k = 1; amplitude > 1e-17 * lowestAmplitude; ++k) {
            amplitude *= std::exp(-0.5 * stepY);
            rate *= std::exp(-stepY);
            exact += amplitude * std::exp(-rate * lag);
        }
        return std::abs(exact - lumped.amplitude * std::exp(-lumped.rate * lag)) * std::sqrt(lag);
    }
};

} // namespace

ExponentialSum ExponentialSum::fit(double window, double horizon, double accuracy,
                                   LowRates lowRates) {
    // Three error sources, each held to accuracy/3 relative to 1/√ℓ on [window, horizon]:
    //  - trapezoid step Δy: aliasing error 2√2 e^{−π²/Δy} (the integrand is analytic in the
    //    strip |Im y| < π/2);
    //  - nodes beyond x_max = X/window: relative error erfc(√(X)) for ℓ ≥ window;
    //  - nodes below the lowest one, x_min: lumped into one term (LumpedNodes), its error
    //    growing with ℓ, so measured at ℓ = horizon and at ten lags per decade below it; or
    //    (LowRates::truncated) left out, relative error erf(√(x_min ℓ)) ≈ 2√(x_min ℓ/π).
    const double part = accuracy / 3.0;
    const double stepY =
        std::numbers::pi * std::numbers::pi / std::log(2.0 * std::sqrt(2.0) / part);
    double upper = 1.0;
    while (std::erfc(std::sqrt(upper)) > part) upper *= 1.1;
    const double longest = std::max(horizon, window);
    const auto amplitudeAt = [&](double y) { return stepY * std::exp(0.5 * y) / rootPi; };
    const auto lumpedError = [&](double y) {
        double worst = 0;
        for (double lag = longest; lag >= window; lag /= 1.2589254117941673) // 10 a decade
            worst = std::max(worst, LumpedNodes::error(amplitudeAt(y), std::exp(y), stepY, lag));
        return worst;
    };
    double lowestY = std::log(upper / window);
    if (lowRates == LowRates::truncated) {
        const double xMin = std::pow(part * rootPi / 2.0, 2) / longest;
        lowestY -= std::ceil((lowestY - std::log(xMin)) / stepY) * stepY;
    } else {
        while (lumpedError(lowestY) > part) lowestY -= stepY;
    }
    ExponentialSum sum; // slowest term first
    if (lowRates == LowRates::lumped) {
        const LumpedNodes lumped(amplitudeAt(lowestY), std::exp(lowestY), stepY);
        sum.amplitude.push_back(lumped.amplitude);
        sum.timescale.push_back(1 / lumped.rate);
    }
    for (double y = lowestY; y <= std::log(upper / window) + 0.5 * stepY; y += stepY) {
        sum.amplitude.push_back(amplitudeAt(y));
        sum.timescale.push_back(std::exp(-y));
    }
    return sum;
}

double ExponentialSum::operator()(double lag) const {
    double value = 0;
    for (std::size_t i = 0; i < size(); ++i) value += amplitude[i] * std::exp(-lag / timescale[i]);
    return value;
}

FullHistory::FullHistory(double h, int order, const Vec3& startRemainder, HistoryKernel kernel)
    : h_(h), order_(order), kernel_(kernel), values_{startRemainder} {}

Vec3 FullHistory::beginStep(double stepLength) {
    const long n = static_cast<long>(values_.size()) - 1; // values ρ_0 … ρ_n
    if (n == 0) firstStep_ = stepLength;
    while (static_cast<long>(weights_.size()) <= n) {
        weights_.push_back(kernelWeight(order_, static_cast<long>(weights_.size()), h_, kernel_));
    }
    newestWeight_ = weights_[0];
    if (firstStep_ != h_) {
        // The first step [0, h'] lags n h behind t_{n+1}: ρ_1 (newest if n = 0) and ρ_0 take
        // its weights for h' in place of those for h.
        const double lag = static_cast<double>(n) * h_;
        const FirstStepWeights actual = firstStepWeights(order_, lag, firstStep_, kernel_);
        const double regular = firstStepWeights(order_, lag, h_, kernel_).newer;
        if (n == 0) {
            newestWeight_ += actual.newer - regular;
            return actual.older * values_[0];
        }
        Vec3 sum = actual.older * values_[0] +
                   (weights_[static_cast<std::size_t>(n)] + actual.newer - regular) * values_[1];
        for (long j = 2; j <= n; ++j)
            sum += weights_[static_cast<std::size_t>(n + 1 - j)] *
                   values_[static_cast<std::size_t>(j)];
        return sum;
    }
    Vec3 sum = kernelEndWeight(order_, n + 1, h_, kernel_) * values_[0];
    for (long j = 1; j <= n; ++j)
        sum += weights_[static_cast<std::size_t>(n + 1 - j)] * values_[static_cast<std::size_t>(j)];
    return sum;
}

WindowTailLayout WindowTailLayout::make(double h, double horizon, double accuracy,
                                        LowRates lowRates) {
    WindowTailLayout layout;
    layout.h = h;
    // The tail integrates ρ piecewise linear against each exponential exactly, so the window
    // only has to cover lags where the sum cannot follow the 1/√ℓ singularity. One more window
    // step costs one node; one more term of the sum covers Δy of ln ℓ: the total is least for a
    // window of about 1/Δy steps.
    const double stepY =
        std::numbers::pi * std::numbers::pi / std::log(2.0 * std::sqrt(2.0) / (accuracy / 3.0));
    layout.window =
        std::clamp(static_cast<int>(std::lround(1.0 / stepY)), 1, WindowTailHistory::largestWindow);
    const double windowLength = layout.window * h;
    layout.tail = ExponentialSum::fit(windowLength, horizon, accuracy, lowRates);
    const double singleLongest = accuracy / 10 * 0x1p24 * h; // 2⁻²⁴ θ/h ≤ accuracy/10
    layout.singleTerms = static_cast<std::size_t>(
        std::count_if(layout.tail.timescale.begin(), layout.tail.timescale.end(),
                      [&](double theta) { return theta <= singleLongest; }));
    const double rootH = std::sqrt(h);
    for (int k = 0; k < layout.window; ++k)
        layout.windowWeights.push_back(rootH * productWeight(2, k));
    layout.windowWeights.push_back(rootH * productEndWeight(2, layout.window));
    for (std::size_t i = 0; i < layout.tail.size(); ++i) {
        const double theta = layout.tail.timescale[i];
        const EndWeights entry = tailEntryWeights(layout.tail.amplitude[i], theta, windowLength, h);
        layout.tailDecay.push_back(std::exp(-h / theta));
        layout.tailNewWeight.push_back(entry.newer);
        layout.tailOldWeight.push_back(entry.older);
    }
    return layout;
}

WindowTailHistory::WindowTailHistory(const WindowTailLayout& layout, double* state,
                                     HistoryKernel kernel)
    : layout_(layout), state_(state), kernel_(kernel) {
    const int window = layout.window;
    std::copy_n(layout.windowWeights.begin(), window + 1, windowWeights_.begin());
    if (kernel.viscousTime == 0) return;
    // Less the bounded part: step p's newer end weighs on lag p, its older end on lag p + 1.
    for (int p = 0; p < window; ++p) {
        const EndWeights step = boundedPartWeights(p * layout.h, layout.h, kernel.viscousTime);
        windowWeights_[static_cast<std::size_t>(p)] -= step.newer;
        windowWeights_[static_cast<std::size_t>(p + 1)] -= step.older;
    }
}

Vec3 WindowTailHistory::beginStep(double stepLength) {
    // State: ρ at lags 0 … window, then the tail sums a_i F_i (amplitude folded in), then the
    // first step's length h' and the steps taken n. The spin kernel's amplitudes are Basset's
    // times t_v x_i/(1 + t_v x_i), x_i = 1/θ_i.
    const int window = layout_.window;
    double& firstStep = counters()[0];
    const auto steps = static_cast<long>(counters()[1]);
    if (steps == 0) firstStep = stepLength;
    const bool shortFirst = firstStep != layout_.h;
    newestWeight_ = windowWeights_[0];
    const Vec3 leavingNewer = lagged(window - 1);
    const Vec3 leavingOlder = lagged(window);
    Vec3 known = windowWeights_[static_cast<std::size_t>(window)] * leavingNewer;
    for (int k = 1; k < window; ++k)
        known += windowWeights_[static_cast<std::size_t>(k)] * lagged(k - 1);
    // A short first step: ρ_1 lags n h and takes the first step's weight for h' (ρ_0 = 0).
    if (shortFirst && steps < window) {
        const double lag = static_cast<double>(steps) * layout_.h;
        const double correction = firstStepWeights(2, lag, firstStep, kernel_).newer -
                                  firstStepWeights(2, lag, layout_.h, kernel_).newer;
        if (steps == 0)
            newestWeight_ += correction;
        else
            known += correction * lagged(static_cast<int>(steps) - 1);
    }
    const bool firstEntersTail = shortFirst && steps == window;
    const double viscousTime = kernel_.viscousTime;
    const bool regular = viscousTime == 0 && !firstEntersTail; // the layout's weights as they are
    const double* decay = layout_.tailDecay.data();
    const double* newerWeight = layout_.tailNewWeight.data();
    const double* olderWeight = layout_.tailOldWeight.data();
    const std::array<double, 3> newer{leavingNewer.x(), leavingNewer.y(), leavingNewer.z()};
    const std::array<double, 3> older{leavingOlder.x(), leavingOlder.y(), leavingOlder.z()};
    std::array<double, 3> total{known.x(), known.y(), known.z()};
    // F_i ← e^{−h/θ_i} F_i + weights · (ρ leaving the window), kept as Sum (double or float)
    // at `bytes` (read and written a component at a time: the state is an array of double),
    // added to the total as kept; the arrays' pointers hoisted, as the state could alias them.
    const auto advance = [&]<typename Sum>(std::size_t i, unsigned char* bytes) {
        double newWeight = newerWeight[i], spectrum = 1.0;
        if (!regular) {
            const double theta = layout_.tail.timescale[i];
            if (viscousTime != 0) spectrum = viscousTime / (theta + viscousTime);
            if (firstEntersTail)
                newWeight = tailEntryWeights(layout_.tail.amplitude[i], theta, window * layout_.h,
                                             firstStep)
                                .newer;
        }
        for (std::size_t c = 0; c < 3; ++c) {
            Sum sum;
            std::memcpy(&sum, bytes + c * sizeof(Sum), sizeof(Sum));
            sum = static_cast<Sum>(decay[i] * sum +
                                   spectrum * (newWeight * newer[c] + olderWeight[i] * older[c]));
            std::memcpy(bytes + c * sizeof(Sum), &sum, sizeof(Sum));
            total[c] += sum;
        }
    };
    const std::size_t doubleTerms = layout_.doubleTerms();
    for (std::size_t i = 0; i < doubleTerms; ++i)
        advance.operator()<double>(i, reinterpret_cast<unsigned char*>(doubleTail() + 3 * i));
    for (std::size_t i = doubleTerms; i < layout_.tail.size(); ++i)
        advance.operator()<float>(i, singleTail() + 3 * sizeof(float) * (i - doubleTerms));
    known = Vec3(total[0], total[1], total[2]);
    return known;
}

void WindowTailHistory::endStep(const Vec3& remainder) {
    std::memmove(state_ + 3, state_, sizeof(double) * 3 * static_cast<std::size_t>(layout_.window));
    Eigen::Map<Vec3> newest(state_);
    newest = remainder;
    counters()[1] += 1; // steps taken
}

StartModeStep startModeStep(double historyRate, const HistoryStart& start, double h,
                            HistoryKernel kernel) {
    if (start.startSlip.isZero(0)) return {};
    if (kernel.viscousTime > 0) {
        return {spinStartMode(historyRate, kernel.viscousTime, start.age),
                spinStartMode(historyRate, kernel.viscousTime, start.age + h)};
    }
    const double alpha = rootPi * historyRate;
    return {startMode(alpha, start.age), startMode(alpha, start.age + h), alpha};
}

template <typename Memory>
StepResult advanceWithHistory(const SlipStep& step, const Vec3& velocity, HistoryStart& start,
                              Memory& memory) {
    return advanceWithHistory(step, velocity, start, memory,
                              startModeStep(step.historyRate, start, step.h, memory.kernel()));
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
    const Vec3 remainderBefore = step.gasStart - velocity - before.value * s0;
    // Basset's memories take the start mode's history in closed form; the finite-Reynolds ones
    // (physics/finite_reynolds_history.h) take it into their own A.
    constexpr bool memoryTakesStartMode = requires(Memory & m) { m.beginStep(h, modes, s0); };
    Vec3 startHistory = (after.history - before.history) * s0;
    Vec3 known;
    if constexpr (memoryTakesStartMode) {
        startHistory.setZero();
        known = memory.beginStep(h, modes, s0);
    } else {
        known = memory.beginStep(h);
    }
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
    if constexpr (memoryTakesStartMode)
        memory.endStep(remainder, modes, s0);
    else
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
template StepResult advanceWithHistory(const SlipStep&, const Vec3&, HistoryStart&,
                                       FiniteReynoldsFullHistory&);
template StepResult advanceWithHistory(const SlipStep&, const Vec3&, HistoryStart&,
                                       FiniteReynoldsWindowTail&);

} // namespace slides
