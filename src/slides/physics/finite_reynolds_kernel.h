// The finite-Reynolds history kernels of Mei & Adrian (Eq. 3.5–3.7) and Kim et al. (Eq. 3.9–3.15)
// as one family, with the integrals and the spectrum the history memories need.
//
// Reference: Mei & Adrian (1992, J. Fluid Mech. 237:323), Kim, Elghobashi & Sirignano (1998,
// J. Fluid Mech. 367:221). Both kernels, per Basset size R/√(πν), are
//   K̂(ℓ; τ) = ℓ^(−½) F(ℓ/ℓ_c(τ)),  F(y) = (1 + y^p)^(−c1),  p = 3/(2 c1),
// c1 = 2 for Mei & Adrian (Eq. 3.5 with its outer exponent −2) and 2.5 for Kim (Eq. 3.9), with
// the crossover lag, where the decay ℓ^(−2) takes over from Basset's ℓ^(−½),
//   ℓ_c = (4/π)^(1/3) ν f_H²/|u − v|² · G^(−1/p),  f_H = 0.75 + c5 Re(τ),  Re = 2R|u − v|/ν,
// (c5 = 0.105, 0.126; G of Eq. 3.10 for Kim, 1 for Mei & Adrian). Then K̂ = ℓ^(−½) at ℓ ≪ ℓ_c.
// The memories (physics/finite_reynolds_history.h) integrate ∫ K̂(t − τ; τ) d(u − v)(τ), which
// needs, per interval of constant ℓ_c, the first and second integrals in the lag,
//   Q(ℓ) = ∫_0^ℓ K̂ = √ℓ_c q(ℓ/ℓ_c),  W(ℓ) = ∫_0^ℓ Q = ℓ_c^(3/2) w(ℓ/ℓ_c),
// and, for the exponential tail, the spectrum of K̂ relative to Basset's: with
// ℓ^(−½) = π^(−½) ∫ e^{−xℓ} x^(−½) dx, K̂ = π^(−½) ∫ e^{−xℓ} x^(−½) κ(x ℓ_c) dx, where (by the
// cut of K̂ along ℓ < 0)
//   κ(X) = π^(−½) ∫_0^∞ e^{−ρ} ρ^(−½) Re[(1 + (ρ/X)^p e^{−iπp})^(−c1)] dρ,
// κ → 1 for X → ∞ (short lags, Basset) and κ ∝ X^(3/2) for X → 0 (the decay ℓ^(−2)). q, w and κ are
// tabulated once per shape on a grid in ln y (quintic Hermite in ln q, ln w from their exact
// derivatives; cubic in ln κ), to about 1e-13 relative for q and w; the kernel rebuilt from κ errs
// 3e-7.
#pragma once

#include <vector>

namespace slides {

/// One member of the family: its exponent c1 and the slope c5 of f_H.
struct FiniteReynoldsShape {
    double exponent;                                ///< c1
    double fHSlope;                                 ///< c5 of f_H = 0.75 + c5 Re
    double power() const { return 1.5 / exponent; } ///< p = 3/(2 c1)
};
inline constexpr FiniteReynoldsShape meiAdrianShape{2.0, 0.105};
inline constexpr FiniteReynoldsShape kimShape{2.5, 0.126};

/// ℓ_c [s] for the slip speed at τ (infinite for no slip: Basset's kernel), with Kim's G.
double crossoverLag(const FiniteReynoldsShape& shape, double slipSpeed, double particleRadius,
                    double kinematicViscosity, double accelerationFactor = 1.0);

/// The tables of one shape; of() builds each once.
class FiniteReynoldsKernel {
public:
    static const FiniteReynoldsKernel& of(const FiniteReynoldsShape& shape);
    explicit FiniteReynoldsKernel(const FiniteReynoldsShape& shape);

    const FiniteReynoldsShape& shape() const { return shape_; }
    /// K̂(ℓ) = ℓ^(−½) F(ℓ/ℓ_c) [1/√s].
    double kernel(double lag, double crossover) const;
    /// Q(ℓ) = ∫_0^ℓ K̂ [√s].
    double firstIntegral(double lag, double crossover) const;
    /// W(ℓ) = ∫_0^ℓ Q [s^(3/2)].
    double secondIntegral(double lag, double crossover) const;
    /// (1/h) ∫_ℓ^{ℓ+h} Q: the weight of a slip increment spread evenly over an interval whose
    /// newer end lags ℓ [√s].
    double intervalWeight(double lag, double length, double crossover) const;
    /// κ(X), X = x ℓ_c.
    double spectrumRatio(double x) const;
    /// κ at ln X (for sums over a ladder of rates x_i with one ℓ_c: ln X = ln x_i + ln ℓ_c).
    double spectrumRatioAtLog(double logX) const;

    /// q(y), w(y) and F(y) of the dimensionless lag y = ℓ/ℓ_c.
    double q(double y) const;
    double w(double y) const;
    double shapeFunction(double y) const;

private:
    FiniteReynoldsShape shape_;
    // Nodes t_k = tMin + k δ of t = ln y (ln X for κ): ln q, ln w and their first two
    // t-derivatives; ln κ.
    std::vector<double> logQ_, logQ1_, logQ2_, logW_, logW1_, logW2_, logKappa_;
    double qInfinity_ = 0, rAtEnd_ = 0; ///< q(∞); ∫_0^{y_max} u^(½) F du
};

} // namespace slides
