// PulsedJet: an analytic jet (carrier/analytic_jet.h, carrier/round_laminar_jet.h) whose nozzle
// velocity pulsates, U0(t) = U0 (1 + A sin 2πft), the pulse carried downstream at the mean jet's
// centreline speed. A kinematic model of a pulsed jet, not a solution of the Navier–Stokes
// equations (a real pulsed jet rolls up into vortex rings, and its pulses steepen and spread).
//
//     carrier { type analyticJet;       // or roundLaminarJet, roundLaminarJetCoeffs
//               analyticJetCoeffs { nozzleVelocity 25; ...;
//                                   pulsation { amplitude 0.3; frequency 100; } } }
//
// Model. The nozzle's velocity signal s(t) = 1 + A sin ωt (ω = 2πf, 0 ≤ A < 1) travels
// downstream at the local centreline speed u_c(a) of the mean (steady) jet, so at axial distance
// a from the exit plane it arrives after the travel time
//   τ(a) = ∫_0^a da'/u_c(a')                                   (SimilarityJet::travelTime):
//   a/U0 through the unentrained core (where u_c = U0), then with s = a − L + s0 (jet_frame.h)
//     sech² jet (Eq. 5.10, u_c = C1 s^(−1/3)):  τ = L/U0 + (3/(4 C1)) (s^(4/3) − s0^(4/3)),
//     round laminar jet (u_c = 3K/(8πν s)):     τ = L/U0 + (s² − s0²)/(2·3K/(8πν)),
// and the gas velocity is the mean jet's scaled by the signal that left the nozzle then,
//   U(x, t) = s(t − τ(a)) U_mean(x)       (the profile's shape that of the mean U0).
// The phase ω(t − τ) is constant along the centreline characteristic da/dt = u_c(a). Then
//   ∂U/∂t = ωA cos ω(t − τ) U_mean,
//   ∇U    = s ∇U_mean + U_mean ⊗ ∇s,   ∇s = −ωA cos ω(t − τ) τ'(a) e_a,   τ' = 1/u_c(a),
// (gradient(i, j) = ∂U_i/∂x_j). Behind the exit plane the gas is at rest, as in the steady jet.
// Over a period U averages to U_mean. k and ε (carrier/jet_scalars.h) stay at the mean jet's:
// the pulsation is resolved in U, not part of the turbulence. ∇²U is not given (as for the
// steady jets: no Faxén terms).
//
// Limits: the mean jet's spreading and entrainment are kept whatever the pulse (a real jet
// entrains more when pulsed); the pulse shape is not deformed by the cross-stream profile (it
// travels at the centreline speed at every radius); the continuity the steady profile satisfies
// is broken by the axial gradient of s: ∇·U = s ∇·U_mean + u_mean ∂s/∂a. Amplitude 0 (or no
// pulsation {}) gives the steady jet itself (carrier/make_carrier.cpp builds no PulsedJet).
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/carrier/jet_frame.h"
#include "slides/core/parallel.h"

#include <cmath>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

namespace slides {

/// `pulsation {}` of the analytic jets' coefficients.
struct JetPulsation {
    double amplitude = 0; ///< A of U0 (1 + A sin 2πft), 0 ≤ A < 1 [1]
    double frequency = 0; ///< f [Hz]
};

/// The nozzle's signal s = 1 + A sin φ and its rate ds/dt = ωA cos φ at phase φ = ω(t − τ).
struct PulseSignal {
    double value = 1; ///< s [1]
    double rate = 0;  ///< ∂s/∂t [1/s]
};

/// Jet (AnalyticJet or RoundLaminarJet) with a pulsed nozzle. Jet needs frame(),
/// centrelineVelocity(a), halfWidth(a) and travelTime(a) (carrier/similarity_jet.h); PulsedJet
/// gives them too (the mean jet's), so JetScalars can wrap it.
template <typename Jet> class PulsedJet final : public CarrierField {
public:
    /// Throws std::invalid_argument unless 0 ≤ amplitude < 1 and frequency > 0 (finite).
    PulsedJet(std::unique_ptr<Jet> jet, const JetPulsation& pulsation)
        : jet_(std::move(jet)), pulsation_(pulsation),
          angularFrequency_(2 * std::numbers::pi * pulsation.frequency) {
        if (!(pulsation.amplitude >= 0 && pulsation.amplitude < 1))
            throw std::invalid_argument("pulsed jet: amplitude must lie in [0, 1), got " +
                                        std::to_string(pulsation.amplitude));
        if (!(std::isfinite(pulsation.frequency) && pulsation.frequency > 0))
            throw std::invalid_argument("pulsed jet: frequency must be positive, got " +
                                        std::to_string(pulsation.frequency));
    }

    /// The signal at axial distance a ≥ 0 and time t: s(t − τ(a)).
    PulseSignal signal(double axialDistance, double time) const {
        const double phase = angularFrequency_ * (time - jet_->travelTime(axialDistance));
        return {1 + pulsation_.amplitude * std::sin(phase),
                angularFrequency_ * pulsation_.amplitude * std::cos(phase)};
    }

    void sample(std::span<const Vec3> points, double time, CarrierNeeds needs,
                CarrierSample& out) const override {
        jet_->sample(points, time, needs, out); // the mean jet; out resized to needs
        const JetNozzle& nozzle = jet_->frame().nozzle();
        const Vec3& axis = nozzle.axis;
        const auto count = static_cast<std::ptrdiff_t>(points.size());
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
        for (std::ptrdiff_t n = 0; n < count; ++n) {
            const auto i = static_cast<std::size_t>(n);
            const double axial = (points[i] - nozzle.centre).dot(axis);
            if (axial < 0) { // at rest behind the exit plane: U = ∇U = 0, and so ∂U/∂t
                if (needs.timeDerivative) out.velocityTimeDerivative[i].setZero();
                continue;
            }
            const PulseSignal s = signal(axial, time);
            const Vec3 mean = out.velocity[i];
            if (needs.velocityGradient) {
                // ∇s = ∂s/∂a e_a, ∂s/∂a = −(∂s/∂t) τ'(a), τ' = 1/u_c(a).
                const double along = -s.rate / jet_->centrelineVelocity(axial);
                Mat3& gradient = out.velocityGradient[i];
                gradient *= s.value;
                gradient.noalias() += mean * (along * axis).transpose();
            }
            if (needs.timeDerivative) out.velocityTimeDerivative[i] = s.rate * mean;
            out.velocity[i] = s.value * mean;
        }
    }

    bool steady() const override { return false; }
    CarrierNeeds provides() const override {
        return {.velocityGradient = true, .timeDerivative = true};
    }
    std::string describe() const override {
        std::ostringstream text;
        text << jet_->describe() << "; pulsed nozzle U0 (1 + " << pulsation_.amplitude << " sin 2π·"
             << pulsation_.frequency << " Hz·t), carried at the centreline speed (kinematic model)";
        return text.str();
    }

    const Jet& jet() const { return *jet_; }
    const JetPulsation& pulsation() const { return pulsation_; }
    // The mean jet's, for JetScalars: k and ε stay at the mean.
    const JetFrame& frame() const { return jet_->frame(); }
    double centrelineVelocity(double axialDistance) const {
        return jet_->centrelineVelocity(axialDistance);
    }
    double halfWidth(double axialDistance) const { return jet_->halfWidth(axialDistance); }
    double travelTime(double axialDistance) const { return jet_->travelTime(axialDistance); }

private:
    std::unique_ptr<Jet> jet_;
    JetPulsation pulsation_;
    double angularFrequency_;
};

} // namespace slides
