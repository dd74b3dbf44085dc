// Basset history integrators: full-memory product quadrature (reference) and a fixed-memory
// window + exponential-sum tail (production), both implicit in the new velocity.
//
// Reference: Eq. 3.2–3.3 of the reference; Daitche (2013, J. Comput. Phys. 254:93) for
// product-integration weights of the 1/√(t − τ) kernel; van Hinsberg, ten Thije Boonkkamp &
// Clercx (2011, J. Comput. Phys. 230:1465) for the window + exponential tail; Jiang & Greengard
// (2004) / Beylkin & Monzón (2010) for the exponential sum of 1/√t by the trapezoid rule in log
// time. The equation of motion per unit effective mass, with slip s = u − v, is
//   dv/dt = s/τ + a + r_H d/dt I(t),   I(t) = ∫_0^t s(τ)/√(t − τ) dτ      (Eq. 3.3)
// and is advanced in its integrated (Volterra) form over a step [t_n, t_n + h]:
//   v_{n+1} = v_n + ∫ s/τ dt + ∫ a dt + r_H (I_{n+1} − I_n).
// Start: a particle released with slip s0 ≠ 0 has s − s0 ∝ √t, which costs every polynomial
// quadrature half an order (Daitche's third-order scheme falls to about 1.5). The slip is split as
// s = s0 φ(t) + ρ(t) with the start mode φ(t) = e^{α²t} erfc(α√t), α = √π r_H, whose √t term is
// the exact one of the solution (v − v0 ≈ 2 r_H s0 √t); φ's integrals are closed form, and the
// remainder ρ = O(t) with ρ(0) = 0 is integrated by the quadrature at full order.
// A particle's first step may be shorter than the others (released inside a step): the nodes
// are then t = 0, h', h' + h, …, and the first interval's weights, which fall on ρ_1 alone
// (ρ_0 = 0), are taken for its length h' (the steps after it must all be h).
// The same machinery integrates the spin's unsteady torque (Eq. 3.19, Feuillebois & Lasek 1978,
// Q. J. Mech. Appl. Math. 31:435), whose kernel is 1/√ℓ less a bounded part (HistoryKernel).
//
//     physics { history { model basset; accuracy 1e-3; } }   // none | basset | meiAdrian | kim
#pragma once

#include "slides/core/vector.h"

#include <array>
#include <span>
#include <string_view>
#include <vector>

namespace slides {

enum class HistoryModel { none, basset, meiAdrian, kim };

struct HistoryModelName {
    HistoryModel value;
    std::string_view name;
};

/// The name table of the history family. How to add one: an enumerator here, its kernel in
/// physics/history_kernel.h (a finite-Reynolds shape in physics/finite_reynolds_kernel.h), and
/// its memory in the Maxey–Riley stepper (integrate/maxey_riley.h).
constexpr std::array<HistoryModelName, 4> historyModelNames() {
    return {{{HistoryModel::none, "none"},
             {HistoryModel::basset, "basset"},
             {HistoryModel::meiAdrian, "meiAdrian"},
             {HistoryModel::kim, "kim"}}};
}

/// e^{x²} erfc(x) for x ≥ 0, without overflow for large x.
double scaledComplementaryError(double x);

/// The kernel k of I(t) = ∫_0^t k(t − τ) s(τ) dτ. Basset's is 1/√ℓ (viscousTime 0). The spin's
/// (Eq. 3.19, in the Laplace domain k̂ = √(π t_v)/(1 + √(t_v p))) is
///   k(ℓ) = 1/√ℓ − √(π/t_v) e^{ℓ/t_v} erfc(√(ℓ/t_v)),  t_v = R²/ν,
/// i.e. 1/√ℓ = π^(−½)∫ e^{−xℓ} x^(−½) dx with its spectrum weighted by t_v x/(1 + t_v x).
struct HistoryKernel {
    double viscousTime = 0; ///< t_v = R²/ν [s]; 0: Basset's 1/√ℓ
};

/// The start mode φ(t) = e^{α²t} erfc(α√t) and its closed-form integrals.
struct StartMode {
    double value;    ///< φ(t)
    double integral; ///< ∫_0^t φ dτ [s]
    double history;  ///< ∫_0^t φ(τ)/√(t − τ) dτ [√s]
};
StartMode startMode(double alpha, double age);
/// The start mode of the spin kernel: φ solves φ + r_H ∫ k φ = 1 (the history-only equation),
///   φ = (1 + b E(c√t))/(1 + b),  b = r_H √(π t_v),  c = (1 + b)/√t_v,  E(x) = e^{x²}erfc(x),
/// with the same √t start as Basset's, so its history integral is (1 − φ)/r_H.
StartMode spinStartMode(double historyRate, double viscousTime, double age);

/// The start mode at both ends of a step [age, age + h]; φ = 1, integrals 0 when s0 = 0.
struct StartModeStep {
    StartMode before{1, 0, 0};
    StartMode after{1, 0, 0};
    double alpha = 0; ///< α of Basset's φ (0 for the spin kernel's or none), for φ inside the step
};
struct HistoryStart;
StartModeStep startModeStep(double historyRate, const HistoryStart& start, double h,
                            HistoryKernel kernel = {});

/// Product-integration weight c_k of the node k steps back in I(t_n) = √h Σ_k c_k ρ_{n−k}
/// for a node inside the integration range: piecewise-constant ρ (order 1, Daitche's first-order
/// weights) or piecewise-linear ρ (order 2).
double productWeight(int order, long lag);
/// Weight of the oldest node ρ_0 when it sits lag steps back (order 2; 0 for order 1).
double productEndWeight(int order, long lag);
/// The same weights for a kernel and step h, in √s: √h c_k for Basset's, less the weights of
/// the spin kernel's bounded part (closed form on the newest step, Gauss–Legendre beyond).
double kernelWeight(int order, long lag, double h, HistoryKernel kernel);
double kernelEndWeight(int order, long lag, double h, HistoryKernel kernel);
/// Weights on the newer node (ρ_1) and the older one (ρ_0, order 2) of a particle's first
/// step, of length firstStep, whose newer end lags `lag` [s] behind the integral's end [√s].
struct FirstStepWeights {
    double newer, older;
};
FirstStepWeights firstStepWeights(int order, double lag, double firstStep, HistoryKernel kernel);

/// The rates of an exponential sum below its lowest node: lumped into one term (the sum of
/// Basset's kernel) or left out (the finite-Reynolds memories, which weigh each term by its
/// spectrum ratio and integrate it to the horizon, physics/finite_reynolds_history.h).
enum class LowRates { lumped, truncated };

/// 1/√ℓ ≈ Σ_i amplitude_i e^{−ℓ/timescale_i} for ℓ in [window, horizon] with relative error
/// below accuracy: the trapezoid rule in y = ln x of 1/√ℓ = π^(−½)∫ e^{−xℓ} x^(−½) dx, its nodes
/// below the lowest one lumped into one term; slowest term first.
struct ExponentialSum {
    std::vector<double> amplitude; ///< [1/√s]
    std::vector<double> timescale; ///< [s]

    static ExponentialSum fit(double window, double horizon, double accuracy,
                              LowRates lowRates = LowRates::lumped);
    double operator()(double lag) const;
    std::size_t size() const { return amplitude.size(); }
};

/// One step of the equation of motion for one particle (all accelerations per effective mass).
struct SlipStep {
    double h = 0;                   ///< step length [s]
    double implicitness = 0.5;      ///< θ: ½ trapezoid (order 2), 1 backward Euler (order 1)
    double dragRate = 0;            ///< 1/τ frozen over the step [1/s]
    double historyRate = 0;         ///< r_H [1/√s]
    Vec3 gasStart = Vec3::Zero();   ///< u at the particle at t_n [m/s]
    Vec3 gasEnd = Vec3::Zero();     ///< u at the particle at t_{n+1} [m/s]
    Vec3 forceStart = Vec3::Zero(); ///< every other acceleration at t_n [m/s²]
    Vec3 forceEnd = Vec3::Zero();   ///< and at t_{n+1} [m/s²]
};

/// What a particle carries besides its memory of ρ: the start slip s0, its age, and I_n of ρ.
struct HistoryStart {
    Vec3 startSlip = Vec3::Zero(); ///< s0 = u − v at release [m/s]; zero: no start treatment
    double age = 0;                ///< time since release at the step start [s]
    Vec3 integral = Vec3::Zero();  ///< I_n of the remainder ρ [m/√s]
};

/// The result of a step: new velocity, displacement ∫ v dt.
struct StepResult {
    Vec3 velocity;
    Vec3 displacement;
};

/// Reference memory: every past ρ_j, O(n) work per step (Daitche 2013 style weights).
class FullHistory {
public:
    /// order 1 or 2; startRemainder is ρ_0 (zero with the start treatment, s0 without).
    FullHistory(double h, int order, const Vec3& startRemainder = Vec3::Zero(),
                HistoryKernel kernel = {});
    HistoryKernel kernel() const { return kernel_; }
    /// Weight of ρ_{n+1} in I_{n+1}, once beginStep has seen the step.
    double newestWeight() const { return newestWeight_; }
    /// √h Σ_{k≥1} c_k ρ_{n+1−k}: the part of I_{n+1} known before ρ_{n+1}, for a step of
    /// length stepLength (h, or shorter on the first).
    Vec3 beginStep(double stepLength);
    void endStep(const Vec3& remainder) { values_.push_back(remainder); }
    std::size_t bytes() const { return values_.capacity() * sizeof(Vec3); }

private:
    double h_;
    int order_;
    HistoryKernel kernel_;
    double newestWeight_ = 0;
    double firstStep_ = 0;
    std::vector<Vec3> values_;    ///< ρ_0 … ρ_n
    std::vector<double> weights_; ///< kernelWeight at lag k, extended as n grows
};

/// Fixed-size description of the window + tail memory shared by every particle.
struct WindowTailLayout {
    double h = 0;
    int window = 1;                    ///< steps integrated exactly (lags 0 … window)
    ExponentialSum tail;               ///< kernel for lags ≥ window·h, slowest term first
    std::vector<double> windowWeights; ///< √h c_k, k = 0 … window−1, and √h·end weight at window
    std::vector<double> tailDecay, tailNewWeight, tailOldWeight; ///< per term, for one step
    /// The last (fastest) terms, whose sums WindowTailHistory keeps in single precision: a sum
    /// that decays by e^{−h/θ} a step and is rounded to float each step can stall up to
    /// 2⁻²⁴ θ/h of itself away from its value (the rounding's fixed point), so a term is single
    /// only where that stays below a tenth of the accuracy target.
    std::size_t singleTerms = 0;

    /// Window and terms from the accuracy target (relative kernel error) for ages up to horizon.
    static WindowTailLayout make(double h, double horizon, double accuracy,
                                 LowRates lowRates = LowRates::lumped);
    std::size_t doubleTerms() const { return tail.size() - singleTerms; }
    /// Doubles per particle: ρ at lags 0 … window, 3 components each; the double tail sums (3
    /// each), the single ones (3 floats each, two to a double); the first step's length and the
    /// steps taken.
    std::size_t doubles() const {
        return 3 * (window + 1 + doubleTerms()) + (3 * singleTerms + 1) / 2 + 2;
    }
};

/// Production memory: a view on one particle's doubles (layout.doubles() of them). The layout
/// is Basset's; the spin kernel takes its window weights and weights its tail terms per particle.
class WindowTailHistory {
public:
    WindowTailHistory(const WindowTailLayout& layout, double* state, HistoryKernel kernel = {});
    HistoryKernel kernel() const { return kernel_; }
    double newestWeight() const { return newestWeight_; }
    /// Advances the tail sums to t_{n+1}; returns the known part of I_{n+1}.
    Vec3 beginStep(double stepLength);
    void endStep(const Vec3& remainder);

    static constexpr int largestWindow = 7; ///< far beyond any accuracy target in double

private:
    Vec3 lagged(int lag) const { return Vec3(state_ + 3 * lag); }
    double* doubleTail() const { return state_ + 3 * (layout_.window + 1); }
    unsigned char* singleTail() const {
        return reinterpret_cast<unsigned char*>(doubleTail() + 3 * layout_.doubleTerms());
    }
    double* counters() const { return state_ + layout_.doubles() - 2; }
    const WindowTailLayout& layout_;
    double* state_;
    HistoryKernel kernel_;
    std::array<double, largestWindow + 1> windowWeights_{}; ///< as layout.windowWeights
    double newestWeight_ = 0;
};

/// No memory: the same step without a history force (added mass, pressure gradient, lift only).
struct NoHistory {
    HistoryKernel kernel() const { return {}; }
    double newestWeight() const { return 0; }
    Vec3 beginStep(double) { return Vec3::Zero(); }
    void endStep(const Vec3&) {}
};

/// Advances v (and x by the returned displacement) over one step with the history term implicit
/// in v_{n+1}; memory is FullHistory or WindowTailHistory. Linear in v for a frozen τ, so one
/// scalar division solves it, and drag as stiff as it likes stays stable.
template <typename Memory>
StepResult advanceWithHistory(const SlipStep& step, const Vec3& velocity, HistoryStart& start,
                              Memory& memory);
/// The same with the step's start modes already evaluated (startModeStep).
template <typename Memory>
StepResult advanceWithHistory(const SlipStep& step, const Vec3& velocity, HistoryStart& start,
                              Memory& memory, const StartModeStep& modes);

} // namespace slides
