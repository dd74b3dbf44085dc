#include "slides/physics/finite_reynolds_history.h"

#include <cmath>
#include <cstring>

namespace slides {

FiniteReynoldsFullHistory::FiniteReynoldsFullHistory(const SlipKernel& kernel,
                                                     const Vec3& releaseSlip, double jumpCrossover)
    : kernel_(kernel), jumpCrossover_(jumpCrossover), slips_{releaseSlip} {}

Vec3 FiniteReynoldsFullHistory::beginStep(double stepLength) {
    const FiniteReynoldsKernel& tables = *kernel_.tables;
    const std::size_t n = slips_.size() - 1;
    const double end = end_ = times_[n] + stepLength;
    newestWeight_ = tables.intervalWeight(0, stepLength, kernel_.crossover(slips_[n]));
    Vec3 known = tables.firstIntegral(end, jumpCrossover_) * slips_[0] - newestWeight_ * slips_[n];
    for (std::size_t j = 0; j < n; ++j) {
        known +=
            (slips_[j + 1] - slips_[j]) *
            tables.intervalWeight(end - times_[j + 1], times_[j + 1] - times_[j], crossovers_[j]);
    }
    return known;
}

void FiniteReynoldsFullHistory::endStep(const Vec3& slip) {
    crossovers_.push_back(kernel_.crossover(0.5 * (slips_.back() + slip)));
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

void FiniteReynoldsWindowTail::enterTail(const Vec3& increment, double lag, double length,
                                         double crossover) {
    // The increment's weight at a later lag ℓ: its exact value at Λ = lag + horizon, less the
    // sum's Σ_i entry_i (e^{−x_i (ℓ − lag)} − e^{−x_i horizon}), entry_i the term's weight now.
    const FiniteReynoldsKernel& tables = *kernel_.tables;
    const ExponentialSum& sum = layout_.base.tail;
    const bool regular = length == layout_.base.h && lag == window_ * layout_.base.h;
    const double oldest = lag + layout_.horizon;
    double constant = length == 0 ? tables.firstIntegral(oldest, crossover)
                                  : tables.intervalWeight(oldest, length, crossover);
    const double logCrossover = std::log(crossover); // +∞ with no slip: κ = 1
    for (std::size_t i = 0; i < terms_; ++i) {
        const double rate = 1 / sum.timescale[i];
        double entry = layout_.entryWeight[i];
        if (!regular) {
            entry = sum.amplitude[i] * std::exp(-rate * lag) / rate;
            if (length > 0) entry *= -std::expm1(-rate * length) / (rate * length);
        }
        entry *= tables.spectrumRatioAtLog(layout_.logRate[i] + logCrossover);
        constant += entry * layout_.horizonDecay[i];
        Eigen::Map<Vec3>(tail() + 3 * i) -= entry * increment;
    }
    Eigen::Map<Vec3>(accumulator()) += constant * increment;
}

Vec3 FiniteReynoldsWindowTail::beginStep(double stepLength) {
    const FiniteReynoldsKernel& tables = *kernel_.tables;
    const double h = layout_.base.h;
    const auto n = static_cast<int>(steps());
    if (n == 0) firstStep() = stepLength;
    const double end = firstStep() + n * h; // t_{n+1}
    newestWeight_ = tables.intervalWeight(0, stepLength, kernel_.crossover(lagged(0)));
    Vec3 known = -newestWeight_ * lagged(0);
    // Interval m, between the slips m and m − 1 steps back from t_n, has its newer end m h
    // before t_{n+1}; the first interval is firstStep long.
    for (int m = 1; m <= std::min(window_ - 1, n); ++m) {
        const double length = m == n ? firstStep() : h;
        known +=
            (lagged(m - 1) - lagged(m)) * tables.intervalWeight(m * h, length, crossovers()[m - 1]);
    }
    if (n < window_) known += tables.firstIntegral(end, jumpCrossover()) * lagged(n);
    for (std::size_t i = 0; i < terms_; ++i) {
        Eigen::Map<Vec3>(tail() + 3 * i) *= layout_.base.tailDecay[i];
    }
    if (n >= window_) {
        const double length = n == window_ ? firstStep() : h;
        enterTail(lagged(window_ - 1) - lagged(window_), window_ * h, length,
                  crossovers()[window_ - 1]);
        if (n == window_) enterTail(lagged(window_), end, 0, jumpCrossover());
    }
    known += Vec3(accumulator());
    for (std::size_t i = 0; i < terms_; ++i) known += Vec3(tail() + 3 * i);
    return known;
}

void FiniteReynoldsWindowTail::endStep(const Vec3& slip) {
    const double crossover = kernel_.crossover(0.5 * (lagged(0) + slip));
    std::memmove(state_ + 3, state_, sizeof(double) * 3 * static_cast<std::size_t>(window_));
    Eigen::Map<Vec3> newest(state_);
    newest = slip;
    std::memmove(crossovers() + 1, crossovers(),
                 sizeof(double) * static_cast<std::size_t>(window_ - 1));
    crossovers()[0] = crossover;
    steps() += 1;
}

} // namespace slides
