// Memories of the finite-Reynolds history force (Eq. 3.4 and 3.8): full (reference) and
// window + exponential tail (production), both implicit in the new velocity.
//
// Reference: Eq. 3.4–3.15 of the reference; the kernels as in physics/finite_reynolds_kernel.h.
// The kernel K̂(t − τ; τ) carries Re at the earlier time τ, so the force is not the derivative
// of a convolution of the slip, as Basset's is, but the integral of the slip's increments:
//   a_H = r_H ∫ K̂(t − τ; τ) ds(τ),  s = u − v,
// over [0, t] with the release's jump s(0) (Mei & Adrian's ∫ from −∞; Kim's separate term K1 of
// Eq. 3.13, with its own G1 of Eq. 3.14). Over a step the velocity takes r_H (A_{n+1} − A_n) with
//   A(t) = ∫ Q(t − τ; τ) ds(τ),  Q = ∫_0^ℓ K̂,
// and with s linear on each interval, whose ℓ_c is taken at its mean slip (order 2 for a smooth
// slip):
//   A_{n+1} = s_0 Q(t_{n+1}; ℓ_c,jump) + Σ_j (s_{j+1} − s_j) [W(L_j + h_j) − W(L_j)]/h_j,
// L_j the lag of interval j's newer end. The newest interval's ℓ_c is taken at s_n, which keeps
// the step linear in v_{n+1}; endStep then stores it at the interval's mean (the velocity after
// any step depends only on the last A, so that O(h) in one interval's ℓ_c costs O(h^(5/2))).
// Production: the intervals of the last `window` steps as above; older ones enter an exponential
// tail, after which each ages by Basset's exponential sum with its amplitudes weighted by the
// spectrum ratio κ(x_i ℓ_c) of that interval (the kernel is completely monotone):
//   Q_j(ℓ) = Q_j(Λ) + Σ_i a_i κ_ij (e^{−x_i Λ} − e^{−x_i ℓ})/x_i,
// exact at Λ, the interval's lag at the end of the run: an accumulator of the constants and one
// decaying sum per term. Tying each interval to its exact Q at the oldest lag keeps the sum's
// error in A from growing with the run (the sum's error in ∫ K̂ would add up over the intervals
// otherwise: Q_∞ depends on each one's ℓ_c).
// Start: a release with slip s0 has s − s0 ∝ √t, as under Basset's kernel (the kernels agree at
// short lags), and the linear slip of the first intervals would err O(h^(3/2)) in A for good.
// With Basset's start mode φ (physics/history_integrator.h) the slip is s = s0 φ + ρ; the
// memories take ρ, keep s at their nodes, and add to A the leading error of the linear φ on
// each interval, from its moment M_j = ∫(τ − τ_mid) φ' dτ (the trapezoid rule of φ less its
// integral, closed form):
//   A ≈ A_linear(s) − s0 Σ_j K̂(t − τ_mid,j; ℓ_c,j) M_j,
// the sum by the window and a scalar exponential tail like the slip's. ℓ_c follows |s|, a series
// in √τ there, so on the first 64 intervals each part's increments average the kernel their own
// way (dρ ∝ dτ; dφ ∝ τ^(−½) dτ, by a 2-point rule in √τ whose two ℓ_c the start mode keeps as a
// mixture). The error is 40–800 times below the naive start's, and converges toward order 2
// (measured in tests/verification/test_finite_reynolds_history.cpp).
//
//     physics { history { model meiAdrian; accuracy 1e-3; } }   // or kim
#pragma once

#include "slides/core/vector.h"
#include "slides/physics/finite_reynolds_kernel.h"
#include "slides/physics/history_integrator.h"

#include <array>
#include <vector>

namespace slides {

/// The kernel of one particle: the shape's tables, its radius and the gas viscosity.
struct SlipKernel {
    const FiniteReynoldsKernel* tables;
    double radius, viscosity;
    /// ℓ_c for a slip (G = 1 inside the integral: see scene keys of physics.history.model).
    double crossover(const Vec3& slip) const {
        return crossoverLag(tables->shape(), slip.norm(), radius, viscosity);
    }
};

/// An interval's ℓ_c for the increments of the remainder ρ, and for those of the start mode
/// s0 φ: two values (at the nodes of a 2-point rule) with their shares of the increment.
struct IntervalCrossovers {
    double remainder;
    std::array<double, 2> startMode;
    double share; ///< of startMode[0]; 1 − share of startMode[1]

    /// The weight of the start mode's increment under a kernel integral f(ℓ_c).
    template <typename Integral> double startModeWeight(const Integral& f) const {
        return share * f(startMode[0]) + (1 - share) * f(startMode[1]);
    }
};

/// Reference memory: every past slip and interval, O(n) work per step, any step lengths.
class FiniteReynoldsFullHistory {
public:
    /// The slip at release, with the crossover of its jump.
    FiniteReynoldsFullHistory(const SlipKernel& kernel, const Vec3& releaseSlip,
                              double jumpCrossover);
    HistoryKernel kernel() const { return {}; }
    double newestWeight() const { return newestWeight_; }
    /// A_{n+1} less its term in ρ_{n+1}, the slip being ρ + s0 φ over the step (s0 = 0: ρ is
    /// the slip).
    Vec3 beginStep(double stepLength, const StartModeStep& modes = {},
                   const Vec3& startSlip = Vec3::Zero());
    void endStep(const Vec3& remainder, const StartModeStep& modes = {},
                 const Vec3& startSlip = Vec3::Zero());

private:
    SlipKernel kernel_;
    double jumpCrossover_;
    double newestWeight_ = 0, end_ = 0;          ///< and t_{n+1}
    std::vector<double> times_{0.0};             ///< t_0 … t_n
    std::vector<Vec3> slips_;                    ///< s_0 … s_n
    std::vector<IntervalCrossovers> crossovers_; ///< ℓ_c of each interval
    std::vector<double> moments_;                ///< M_j of the start mode on each interval
    std::vector<double> phis_{1.0};              ///< φ_0 … φ_n
};

/// M = ∫(τ − τ_mid) φ' dτ of the start mode over a step of length h: h (φ_a + φ_b)/2 − ∫φ.
inline double startModeMoment(const StartModeStep& modes, double h) {
    return 0.5 * h * (modes.before.value + modes.after.value) -
           (modes.after.integral - modes.before.integral);
}

/// The Basset layout and what the production memory adds to it: per tail term, the entry
/// weight a_i e^{−x_i L_w}(1 − e^{−x_i h})/(x_i² h) of a regular interval, its decay over the
/// run, and the weight a_i e^{−x_i (L_w + h/2)} of its start-mode moment.
struct FiniteReynoldsLayout {
    WindowTailLayout base;
    double horizon = 0; ///< the run's length: Λ = entry lag + horizon
    std::vector<double> entryWeight;
    std::vector<double> horizonDecay; ///< e^{−x_i horizon}
    std::vector<double> logRate;      ///< ln x_i
    std::vector<double> momentWeight; ///< a_i e^{−x_i (L_w + h/2)}

    static FiniteReynoldsLayout make(const WindowTailLayout& base, double horizon);
    /// Doubles per particle: slips at lags 0 … window; per window interval its crossovers (4),
    /// start-mode moment and increment of φ; per tail term the sums of the remainder's
    /// increments (3), the start mode's and its moments; the accumulators of the remainder (3)
    /// and of the start mode; the first step's length, the steps taken and the jump's crossover.
    std::size_t doubles() const {
        return 3 * (base.window + 1) + 6 * base.window + 5 * base.tail.size() + 4 + 3;
    }
};

/// Production memory: a view on one particle's layout.doubles() doubles.
class FiniteReynoldsWindowTail {
public:
    FiniteReynoldsWindowTail(const FiniteReynoldsLayout& layout, double* state,
                             const SlipKernel& kernel);
    /// At release: the slip and its jump's crossover.
    void start(const Vec3& releaseSlip, double jumpCrossover);
    HistoryKernel kernel() const { return {}; }
    double newestWeight() const { return newestWeight_; }
    /// As FiniteReynoldsFullHistory.
    Vec3 beginStep(double stepLength, const StartModeStep& modes = {},
                   const Vec3& startSlip = Vec3::Zero());
    void endStep(const Vec3& remainder, const StartModeStep& modes = {},
                 const Vec3& startSlip = Vec3::Zero());

private:
    /// One increment entering the tail, or the jump (length 0, no start mode).
    struct TailEntry {
        Vec3 remainder;     ///< increment of ρ (or the jump)
        double startMode;   ///< increment of φ
        double moment;      ///< M of the interval
        double lag, length; ///< its newer end's lag now, and its length [s]
        IntervalCrossovers crossovers;
    };

    Vec3 lagged(int lag) const { return Vec3(state_ + 3 * lag); }
    /// Per window interval: its IntervalCrossovers, 4 doubles.
    double* crossovers() const { return state_ + 3 * (window_ + 1); }
    IntervalCrossovers crossoversOf(int interval) const {
        const double* c = crossovers() + 4 * interval;
        return {c[0], {c[1], c[2]}, c[3]};
    }
    double* moments() const { return crossovers() + 4 * window_; }
    double* startIncrements() const { return moments() + window_; }
    double* tail() const { return startIncrements() + window_; }
    double* startTail() const { return tail() + 3 * terms_; }
    double* momentTail() const { return startTail() + terms_; }
    double* accumulator() const { return momentTail() + terms_; }
    double& startAccumulator() const { return accumulator()[3]; }
    double& firstStep() const { return accumulator()[4]; }
    double& steps() const { return accumulator()[5]; }
    double& jumpCrossover() const { return accumulator()[6]; }
    void enterTail(const TailEntry& entry);
    /// Weights of an entry for one term i: its entry weight now and that of its moment.
    struct TermWeights {
        double entry, moment;
    };
    TermWeights termWeights(std::size_t i, double lag, double length, bool regular) const;

    const FiniteReynoldsLayout& layout_;
    double* state_;
    SlipKernel kernel_;
    int window_;
    std::size_t terms_;
    double newestWeight_ = 0;
};

} // namespace slides
