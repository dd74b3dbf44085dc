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
// and with s linear on each interval, whose ℓ_c is taken at its mean slip (order 2):
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
// No start mode: a release with slip has s − s(0) ∝ √t, and both memories lose order there
// (measured in tests/verification/test_finite_reynolds_history.cpp).
//
//     physics { history { model meiAdrian; accuracy 1e-3; } }   // or kim
#pragma once

#include "slides/core/vector.h"
#include "slides/physics/finite_reynolds_kernel.h"
#include "slides/physics/history_integrator.h"

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

/// Reference memory: every past slip and interval, O(n) work per step, any step lengths.
class FiniteReynoldsFullHistory {
public:
    /// The slip at release, with the crossover of its jump.
    FiniteReynoldsFullHistory(const SlipKernel& kernel, const Vec3& releaseSlip,
                              double jumpCrossover);
    HistoryKernel kernel() const { return {}; }
    double newestWeight() const { return newestWeight_; }
    /// A_{n+1} less its term in s_{n+1}.
    Vec3 beginStep(double stepLength);
    void endStep(const Vec3& slip);

private:
    SlipKernel kernel_;
    double jumpCrossover_;
    double newestWeight_ = 0, end_ = 0; ///< and t_{n+1}
    std::vector<double> times_{0.0};    ///< t_0 … t_n
    std::vector<Vec3> slips_;           ///< s_0 … s_n
    std::vector<double> crossovers_;    ///< ℓ_c of each interval
};

/// The Basset layout and what the production memory adds to it: per tail term, the entry
/// weight a_i e^{−x_i L_w}(1 − e^{−x_i h})/(x_i² h) of a regular interval, and its decay
/// over the run.
struct FiniteReynoldsLayout {
    WindowTailLayout base;
    double horizon = 0; ///< the run's length: Λ = entry lag + horizon
    std::vector<double> entryWeight;
    std::vector<double> horizonDecay; ///< e^{−x_i horizon}
    std::vector<double> logRate;      ///< ln x_i

    static FiniteReynoldsLayout make(const WindowTailLayout& base, double horizon);
    /// Doubles per particle: slips at lags 0 … window, the window's crossovers, the tail sums,
    /// the accumulator, the first step's length, the steps taken and the jump's crossover.
    std::size_t doubles() const {
        return 3 * (base.window + 1) + base.window + 3 * base.tail.size() + 3 + 3;
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
    Vec3 beginStep(double stepLength);
    void endStep(const Vec3& slip);

private:
    Vec3 lagged(int lag) const { return Vec3(state_ + 3 * lag); }
    double* crossovers() const { return state_ + 3 * (window_ + 1); }
    double* tail() const { return crossovers() + window_; }
    double* accumulator() const { return tail() + 3 * terms_; }
    double& firstStep() const { return accumulator()[3]; }
    double& steps() const { return accumulator()[4]; }
    double& jumpCrossover() const { return accumulator()[5]; }
    /// Adds a slip increment entering the tail at `lag` [s], spread over `length` (0: the jump).
    void enterTail(const Vec3& increment, double lag, double length, double crossover);

    const FiniteReynoldsLayout& layout_;
    double* state_;
    SlipKernel kernel_;
    int window_;
    std::size_t terms_;
    double newestWeight_ = 0;
};

} // namespace slides
