#include "slides/carrier/make_carrier.h"

#include "slides/carrier/analytic_jet.h"
#include "slides/carrier/jet_scalars.h"
#include "slides/carrier/round_laminar_jet.h"

namespace slides {

std::unique_ptr<CarrierField> makeCarrier(const Scene& scene) {
    const CarrierSettings& carrier = scene.carrier;
    // k, ε and T only for a scene whose models ask for them; otherwise the bare jet.
    const bool needsScalars = scene.physics.dispersion != DispersionModel::none ||
                              scene.physics.heatTransfer != HeatTransferModel::none;
    const auto withScalars = [&]<typename Jet>(std::unique_ptr<Jet> jet) {
        if (!needsScalars) return std::unique_ptr<CarrierField>(std::move(jet));
        return std::unique_ptr<CarrierField>(std::make_unique<JetScalars<Jet>>(
            std::move(jet), carrier.turbulence, scene.fluid.temperature));
    };
    switch (carrier.type) {
    case CarrierType::analyticJet:
        return withScalars(std::make_unique<AnalyticJet>(
            scene.nozzle,
            AnalyticJetParameters{carrier.profile, carrier.nozzleVelocity, carrier.viscosity,
                                  carrier.coreLength, carrier.C1, carrier.C2, carrier.C3}));
    case CarrierType::roundLaminarJet:
        return withScalars(std::make_unique<RoundLaminarJet>(
            scene.nozzle, RoundLaminarJetParameters{carrier.nozzleVelocity, carrier.viscosity,
                                                    carrier.coreLength}));
    }
    throw std::logic_error("carrier type without a constructor");
}

} // namespace slides
