#include "slides/carrier/make_carrier.h"

#include "slides/carrier/analytic_jet.h"
#include "slides/carrier/foam_carrier.h"
#include "slides/carrier/round_laminar_jet.h"

namespace slides {

std::unique_ptr<CarrierField> makeCarrier(const Scene& scene) {
    const CarrierSettings& carrier = scene.carrier;
    switch (carrier.type) {
    case CarrierType::analyticJet:
        return std::make_unique<AnalyticJet>(
            scene.nozzle,
            AnalyticJetParameters{carrier.profile, carrier.nozzleVelocity, carrier.viscosity,
                                  carrier.coreLength, carrier.C1, carrier.C2, carrier.C3});
    case CarrierType::roundLaminarJet:
        return std::make_unique<RoundLaminarJet>(
            scene.nozzle, RoundLaminarJetParameters{carrier.nozzleVelocity, carrier.viscosity,
                                                    carrier.coreLength});
    case CarrierType::foamField:
        return std::make_unique<FoamCarrier>(
            scene.caseDirectory, FoamCarrierSettings{carrier.foamTime, carrier.interpolation});
    }
    throw std::logic_error("carrier type without a constructor");
}

} // namespace slides
