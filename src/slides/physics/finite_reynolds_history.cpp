#include "slides/physics/finite_reynolds_history.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <numbers>

namespace slides {

namespace {

/// The crossovers of an interval [t_a, t_b] after a release with slip s0, with s = s0 φ(τ) + ρ,
/// ρ linear over the interval. ℓ_c varies there as a series in √τ, and the kernel must be
/// averaged over the interval as each part's increments are: dρ ∝ dτ, but s0 dφ = s0 φ' dτ with
/// φ' ∝ τ^(−½) at first. One ℓ_c at the nodes' mean slip misses by O(h/j) on interval j,
/// O(h^(3/2)) in A in all; so the remainder takes the dτ-weighted mean of ℓ_c, and the start
/// mode, whose increments are larger (∝ √h), the 2-point Gauss–Legendre rule itself, in u = √τ
/// (where ℓ_c is smooth) weighted by dφ/du = 2u α² φ − 2α/√π: its kernel is the mixture of two.
IntervalCrossovers crossoversAfterRelease(const SlipKernel& kernel, double alpha,
                                          const Vec3& startSlip, double start,
                                          const Vec3& remainderStart, double end,
                                          const Vec3& remainderEnd) {
    const double a = std::sqrt(start), b = std::sqrt(end), offset = 0.5 / std::sqrt(3.0);
    IntervalCrossovers crossovers{0, {0, 0}, 0};
    double remainderWeights = 0;
    std::array<double, 2> startWeights{};
    for (std::size_t k = 0; k < 2; ++k) {
        const double u = 0.5 * (a + b) + (k == 0 ? -offset : offset) * (b - a);
        const double phi = scaledComplementaryError(alpha * u);
        const double fraction = (u * u - start) / (end - start);
        const double crossover = kernel.crossover(
            phi * startSlip + (1 - fraction) * remainderStart + fraction * remainderEnd);
        crossovers.remainder += 2 * u * crossover;
        remainderWeights += 2 * u;
        crossovers.startMode[k] = crossover;
        startWeights[k] = 2 * u * alpha * alpha * phi - 2 * alpha / std::sqrt(std::numbers::pi);
    }
    crossovers.remainder /= remainderWeights;
    crossovers.share = startWeights[0] / (startWeights[0] + startWeights[1]);
    return crossovers;
}

/// Intervals after a release whose ℓ_c is weighted per part. Beyond them both weightings agree
/// with the nodes' mean to O(h²/j) on interval j, and Σ_j>64 of what that leaves is below a
/// tenth of the first intervals' share; one ℓ_c then serves both parts (one κ per tail term).
constexpr std::size_t weightedIntervals = 64;

/// The crossovers of interval `index` after release, [start, end], from the slip before it and
/// the remainder ρ after it.
IntervalCrossovers newInterval(const SlipKernel& kernel, const StartModeStep& modes,
                               const Vec3& startSlip, std::size_t index, double start, double end,
                               const Vec3& slipBefore, const Vec3& remainder) {
    if (modes.alpha > 0 && index < weightedIntervals) {
        return crossoversAfterRelease(kernel, modes.alpha, startSlip, start,
                                      slipBefore - modes.before.value * startSlip, end, remainder);
    }
    const double crossover =
        kernel.crossover(0.5 * (slipBefore + remainder + modes.after.value * startSlip));
    return {crossover, {crossover, crossover}, 1};
}

} // namespace

FiniteReynoldsFullHistory::FiniteReynoldsFullHistory(const SlipKernel& kernel,
                                                     const Vec3& releaseSlip, double jumpCrossover)
    : kernel_(kernel), jumpCrossover_(jumpCrossover), slips_{releaseSlip} {}

Vec3 FiniteReynoldsFullHistory::beginStep(double stepLength, const StartModeStep& modes,
                                          const Vec3& startSlip) {
    const FiniteReynoldsKernel& tables = *kernel_.tables;
    const std::size_t n = slips_.size() - 1;
    const double end = end_ = times_[n] + stepLength;
    const double newestCrossover = kernel_.crossover(slips_[n]);
    newestWeight_ = tables.intervalWeight(0, stepLength, newestCrossover);
    // s_{n+1} = ρ_{n+1} + s0 φ_{n+1}: the start mode's part of the newest slip is known.
    Vec3 known = tables.firstIntegral(end, jumpCrossover_) * slips_[0] +
                 newestWeight_ * (modes.after.value * startSlip - slips_[n]);
    double momentSum =
        tables.kernel(0.5 * stepLength, newestCrossover) * startModeMoment(modes, stepLength);
    for (std::size_t j = 0; j < n; ++j) {
        const double lag = end - times_[j + 1], length = times_[j + 1] - times_[j];
        const Vec3 startModeIncrement = (phis_[j + 1] - phis_[j]) * startSlip;
        const IntervalCrossovers& crossovers = crossovers_[j];
        known += (slips_[j + 1] - slips_[j] - startModeIncrement) *
                     tables.intervalWeight(lag, length, crossovers.remainder) +
                 startModeIncrement * crossovers.startModeWeight([&](double crossover) {
                     return tables.intervalWeight(lag, length, crossover);
                 });
        momentSum += moments_[j] * crossovers.startModeWeight([&](double crossover) {
            return tables.kernel(lag + 0.5 * length, crossover);
        });
    }
    return known - momentSum * startSlip;
}

void FiniteReynoldsFullHistory::endStep(const Vec3& remainder, const StartModeStep& modes,
                                        const Vec3& startSlip) {
    const Vec3 slip = remainder + modes.after.value * startSlip;
    const double start = times_.back(), length = end_ - start;
    crossovers_.push_back(newInterval(kernel_, modes, startSlip, crossovers_.size(), start, end_,
                                      slips_.back(), remainder));
    moments_.push_back(startModeMoment(modes, length));
    phis_.push_back(modes.after.value);
    slips_.push_back(slip);
    times_.push_back(end_);
}

FiniteReynoldsLayout FiniteReynoldsLayout::make(const WindowTailLayout& base, double horizon) {
    FiniteReynoldsLayout layout;
    layout.base = base;
    layout.horizon = horizon;
    const double h = base.h, windowLength = base.window * h;
    for (std::size_t i = 0; i < base.tail.size(); ++i) {
        const double rate = 1 / base.tail.timescale[i];
        layout.entryWeight.push_back(base.tail.amplitude[i] * std::exp(-rate * windowLength) *
                                     -std::expm1(-rate * h) / (rate * rate * h));
        layout.horizonDecay.push_back(std::exp(-rate * horizon));
        layout.logRate.push_back(std::log(rate));
        layout.momentWeight.push_back(base.tail.amplitude[i] *
                                      std::exp(-rate * (windowLength + 0.5 * h)));
    }
    return layout;
}

FiniteReynoldsWindowTail::FiniteReynoldsWindowTail(const FiniteReynoldsLayout& layout,
                                                   double* state, const SlipKernel& kernel)
    : layout_(layout), state_(state), kernel_(kernel), window_(layout.base.window),
      terms_(layout.base.tail.size()) {}

void FiniteReynoldsWindowTail::start(const Vec3& releaseSlip, double jumpCrossover) {
    std::memset(state_, 0, sizeof(double) * layout_.doubles());
    Eigen::Map<Vec3> newest(state_);
    newest = releaseSlip;
    this->jumpCrossover() = jumpCrossover;
}

FiniteReynoldsWindowTail::TermWeights FiniteReynoldsWindowTail::termWeights(std::size_t i,
                                                                            double lag,
                                                                            double length,
                                                                            bool regular) const {
    if (regular) return {layout_.entryWeight[i], layout_.momentWeight[i]};
    const ExponentialSum& sum = layout_.base.tail;
    const double rate = 1 / sum.timescale[i];
    double entry = sum.amplitude[i] * std::exp(-rate * lag) / rate;
    if (length > 0) entry *= -std::expm1(-rate * length) / (rate * length);
    return {entry, sum.amplitude[i] * std::exp(-rate * (lag + 0.5 * length))};
}

void FiniteReynoldsWindowTail::enterTail(const TailEntry& entry) {
    // Each increment's weight at a later lag ℓ: its exact value at Λ = lag + horizon, less the
    // sum's Σ_i w_i κ_i (e^{−x_i (ℓ − lag)} − e^{−x_i horizon}), w_i the term's weight now;
    // the moment's, the sum of K̂ at the interval's middle.
    const FiniteReynoldsKernel& tables = *kernel_.tables;
    const bool regular = entry.length == layout_.base.h && entry.lag == window_ * layout_.base.h;
    const double oldest = entry.lag + layout_.horizon;
    const auto exactAtOldest = [&](double crossover) {
        return entry.length == 0 ? tables.firstIntegral(oldest, crossover)
                                 : tables.intervalWeight(oldest, entry.length, crossover);
    };
    const bool startMode = entry.startMode != 0 || entry.moment != 0;
    const IntervalCrossovers& crossovers = entry.crossovers;
    const bool oneCrossover = crossovers.startMode[0] == crossovers.remainder &&
                              crossovers.startMode[1] == crossovers.remainder;
    double constant = exactAtOldest(crossovers.remainder);
    double startConstant = startMode ? crossovers.startModeWeight(exactAtOldest) : 0;
    const double logRemainder = std::log(crossovers.remainder); // +∞ with no slip: κ = 1
    const std::array<double, 2> logStart{std::log(crossovers.startMode[0]),
                                         std::log(crossovers.startMode[1])};
    for (std::size_t i = 0; i < terms_; ++i) {
        const TermWeights weights = termWeights(i, entry.lag, entry.length, regular);
        const double decay = layout_.horizonDecay[i];
        const double logRate = layout_.logRate[i];
        const double remainderKappa = tables.spectrumRatioAtLog(logRate + logRemainder);
        const double remainderWeight = weights.entry * remainderKappa;
        constant += remainderWeight * decay;
        Eigen::Map<Vec3>(tail() + 3 * i) -= remainderWeight * entry.remainder;
        if (!startMode) continue;
        const double kappa =
            oneCrossover
                ? remainderKappa
                : crossovers.share * tables.spectrumRatioAtLog(logRate + logStart[0]) +
                      (1 - crossovers.share) * tables.spectrumRatioAtLog(logRate + logStart[1]);
        startConstant += weights.entry * kappa * decay;
        startTail()[i] -= weights.entry * kappa * entry.startMode;
        momentTail()[i] += weights.moment * kappa * entry.moment;
    }
    Eigen::Map<Vec3>(accumulator()) += constant * entry.remainder;
    startAccumulator() += startConstant * entry.startMode;
}

Vec3 FiniteReynoldsWindowTail::beginStep(double stepLength, const StartModeStep& modes,
                                         const Vec3& startSlip) {
    const FiniteReynoldsKernel& tables = *kernel_.tables;
    const double h = layout_.base.h;
    const auto n = static_cast<int>(steps());
    if (n == 0) firstStep() = stepLength;
    const double end = firstStep() + n * h; // t_{n+1}
    const double newestCrossover = kernel_.crossover(lagged(0));
    newestWeight_ = tables.intervalWeight(0, stepLength, newestCrossover);
    // s_{n+1} = ρ_{n+1} + s0 φ_{n+1}: the start mode's part of the newest slip is known.
    Vec3 known = newestWeight_ * (modes.after.value * startSlip - lagged(0));
    double startSum = 0;
    double momentSum =
        tables.kernel(0.5 * stepLength, newestCrossover) * startModeMoment(modes, stepLength);
    // Interval m, between the slips m and m − 1 steps back from t_n, has its newer end m h
    // before t_{n+1}; the first interval is firstStep long.
    for (int m = 1; m <= std::min(window_ - 1, n); ++m) {
        const double length = m == n ? firstStep() : h;
        const double startIncrement = startIncrements()[m - 1];
        const IntervalCrossovers crossovers = crossoversOf(m - 1);
        known += (lagged(m - 1) - lagged(m) - startIncrement * startSlip) *
                 tables.intervalWeight(m * h, length, crossovers.remainder);
        startSum += startIncrement * crossovers.startModeWeight([&](double crossover) {
            return tables.intervalWeight(m * h, length, crossover);
        });
        momentSum += moments()[m - 1] * crossovers.startModeWeight([&](double crossover) {
            return tables.kernel(m * h + 0.5 * length, crossover);
        });
    }
    if (n < window_) known += tables.firstIntegral(end, jumpCrossover()) * lagged(n);
    for (std::size_t i = 0; i < terms_; ++i) {
        Eigen::Map<Vec3>(tail() + 3 * i) *= layout_.base.tailDecay[i];
        startTail()[i] *= layout_.base.tailDecay[i];
        momentTail()[i] *= layout_.base.tailDecay[i];
    }
    if (n >= window_) {
        const int m = window_ - 1; // the interval leaving the window
        const double startIncrement = startIncrements()[m];
        enterTail({lagged(m) - lagged(window_) - startIncrement * startSlip, startIncrement,
                   moments()[m], window_ * h, n == window_ ? firstStep() : h, crossoversOf(m)});
        const double jump = jumpCrossover();
        if (n == window_) enterTail({lagged(window_), 0, 0, end, 0, {jump, {jump, jump}, 1}});
    }
    known += Vec3(accumulator());
    startSum += startAccumulator();
    for (std::size_t i = 0; i < terms_; ++i) {
        known += Vec3(tail() + 3 * i);
        startSum += startTail()[i];
        momentSum += momentTail()[i];
    }
    return known + (startSum - momentSum) * startSlip;
}

void FiniteReynoldsWindowTail::endStep(const Vec3& remainder, const StartModeStep& modes,
                                       const Vec3& startSlip) {
    const Vec3 slip = remainder + modes.after.value * startSlip;
    const double length = steps() == 0 ? firstStep() : layout_.base.h;
    const double start = steps() == 0 ? 0.0 : firstStep() + (steps() - 1) * layout_.base.h;
    const IntervalCrossovers crossovers =
        newInterval(kernel_, modes, startSlip, static_cast<std::size_t>(steps()), start,
                    start + length, lagged(0), remainder);
    std::memmove(state_ + 3, state_, sizeof(double) * 3 * static_cast<std::size_t>(window_));
    Eigen::Map<Vec3> newest(state_);
    newest = slip;
    const auto older = sizeof(double) * static_cast<std::size_t>(window_ - 1);
    std::memmove(this->crossovers() + 4, this->crossovers(), 4 * older);
    for (double* perInterval : {moments(), startIncrements()})
        std::memmove(perInterval + 1, perInterval, older);
    const std::array<double, 4> newestCrossovers{crossovers.remainder, crossovers.startMode[0],
                                                 crossovers.startMode[1], crossovers.share};
    std::copy(newestCrossovers.begin(), newestCrossovers.end(), this->crossovers());
    moments()[0] = startModeMoment(modes, length);
    startIncrements()[0] = modes.after.value - modes.before.value;
    steps() += 1;
}

} // namespace slides
