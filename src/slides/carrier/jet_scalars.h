// JetScalars: the turbulence (k, ε) and temperature T of an analytic jet, from dictionary input,
// for the dispersion and heat-transfer models (physics/dispersion.h, physics/heat_transfer.h).
// The analytic profiles are laminar similarity solutions: k and ε are not part of them, so
// they are given as a turbulence intensity I and a length scale ℓ, the usual inlet
// specification of k-ε solvers (e.g. OpenFOAM's turbulentIntensityKineticEnergyInlet and
// turbulentMixingLengthDissipationRateInlet):
//   k = (3/2) (I U_ref)²,   ε = C_μ^(3/4) k^(3/2) / ℓ   (C_μ = 0.09).
//
//     carrier { turbulence { scaling uniform; intensity 0.05; lengthScale 1e-3; } }
//     carrier { turbulence { scaling jetLocal; intensity 0.2; lengthScaleToHalfWidth 0.2; } }
//
// uniform:  U_ref = the nozzle velocity U0 and ℓ = lengthScale, everywhere.
// jetLocal: at each axial station a, U_ref = the local centreline velocity U_c(a) and
//           ℓ = lengthScaleToHalfWidth × the local half-width b½(a) (where u = U_c/2), uniform
//           across the jet (the self-similar round jet has u'/U_c ≈ 0.25 and ℓ/b½ ≈ 0.2 on its
//           axis, Pope, Turbulent Flows §5.1). Behind the nozzle exit the gas is at rest:
//           k = ε = 0 (laminar).
// T is the uniform fluid.temperature. The wrapper fills only what a caller asks for; the
// velocity (and gradient) come from the jet unchanged, and a scene that needs neither k, ε nor
// T uses the jet directly (carrier/make_carrier.cpp).
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/carrier/jet_frame.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

namespace slides {

enum class TurbulenceScaling { uniform, jetLocal };

/// `carrier.turbulence {}`.
struct JetTurbulence {
    TurbulenceScaling scaling = TurbulenceScaling::uniform;
    double intensity = 0;              ///< I = u'/U_ref
    double lengthScale = 0;            ///< ℓ [m] (uniform)
    double lengthScaleToHalfWidth = 0; ///< ℓ / b½ (jetLocal)
};

/// k [m²/s²] and ε [m²/s³] for intensity I of velocity U and mixing length ℓ; zero for U = 0.
struct TurbulenceLevel {
    double k = 0;
    double epsilon = 0;
};

inline TurbulenceLevel turbulenceFromIntensity(double intensity, double velocity, double length) {
    constexpr double Cmu = 0.09;
    const double fluctuation = intensity * velocity;
    const double k = 1.5 * fluctuation * fluctuation;
    if (!(k > 0)) return {};
    return {k, std::pow(Cmu, 0.75) * k * std::sqrt(k) / length};
}

/// Jet (AnalyticJet, RoundLaminarJet or either pulsed, carrier/pulsed_jet.h) with k, ε and T.
/// Jet needs frame(), centrelineVelocity(a) and halfWidth(a) (a pulsed jet's are the mean's).
template <typename Jet> class JetScalars final : public CarrierField {
public:
    JetScalars(std::unique_ptr<Jet> jet, std::optional<JetTurbulence> turbulence,
               double temperature)
        : jet_(std::move(jet)), turbulence_(turbulence), temperature_(temperature) {}

    void sample(std::span<const Vec3> points, double time, CarrierNeeds needs,
                CarrierSample& out) const override {
        jet_->sample(points, time, needs, out);
        if (needs.temperature)
            std::fill(out.temperature.begin(), out.temperature.end(), temperature_);
        if (needs.turbulence) sampleTurbulence(points, out);
    }

    /// Steady unless the jet pulsates (carrier/pulsed_jet.h), which then gives ∂U/∂t.
    bool steady() const override { return jet_->steady(); }
    CarrierNeeds provides() const override {
        return {.velocityGradient = true,
                .turbulence = turbulence_.has_value(),
                .temperature = true,
                .timeDerivative = !jet_->steady()};
    }
    std::string describe() const override {
        std::ostringstream text;
        text << jet_->describe() << "; gas temperature " << temperature_ << " K";
        if (turbulence_)
            text << "; turbulence intensity " << turbulence_->intensity
                 << (turbulence_->scaling == TurbulenceScaling::uniform
                         ? " of U0, length scale " + std::to_string(turbulence_->lengthScale) + " m"
                         : " of the centreline velocity, length scale " +
                               std::to_string(turbulence_->lengthScaleToHalfWidth) +
                               " half-widths");
        return text.str();
    }

    const Jet& jet() const { return *jet_; }

private:
    void sampleTurbulence(std::span<const Vec3> points, CarrierSample& out) const {
        if (!turbulence_) { // laminar
            std::fill(out.turbulentKineticEnergy.begin(), out.turbulentKineticEnergy.end(), 0.0);
            std::fill(out.dissipationRate.begin(), out.dissipationRate.end(), 0.0);
            return;
        }
        const JetTurbulence& input = *turbulence_;
        const JetNozzle& nozzle = jet_->frame().nozzle();
        if (input.scaling == TurbulenceScaling::uniform) {
            const TurbulenceLevel level = turbulenceFromIntensity(
                input.intensity, jet_->centrelineVelocity(0.0), input.lengthScale);
            std::fill(out.turbulentKineticEnergy.begin(), out.turbulentKineticEnergy.end(),
                      level.k);
            std::fill(out.dissipationRate.begin(), out.dissipationRate.end(), level.epsilon);
            return;
        }
        for (std::size_t i = 0; i < points.size(); ++i) {
            const double axial = (points[i] - nozzle.centre).dot(nozzle.axis);
            TurbulenceLevel level; // at rest behind the exit plane
            if (axial >= 0)
                level =
                    turbulenceFromIntensity(input.intensity, jet_->centrelineVelocity(axial),
                                            input.lengthScaleToHalfWidth * jet_->halfWidth(axial));
            out.turbulentKineticEnergy[i] = level.k;
            out.dissipationRate[i] = level.epsilon;
        }
    }

    std::unique_ptr<Jet> jet_;
    std::optional<JetTurbulence> turbulence_;
    double temperature_;
};

} // namespace slides
