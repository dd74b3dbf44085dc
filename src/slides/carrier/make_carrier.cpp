#include "slides/carrier/make_carrier.h"

#include "slides/carrier/analytic_jet.h"
#include "slides/carrier/round_laminar_jet.h"

namespace slides {

std::unique_ptr<CarrierField> makeCarrier(const Scene& scene) {
    switch (scene.carrier.type) {
    case CarrierType::analyticJet:
        return std::make_unique<AnalyticJet>(scene.nozzle, scene.carrier);
    case CarrierType::roundLaminarJet:
        return std::make_unique<RoundLaminarJet>(scene.nozzle, scene.carrier);
    }
    throw std::logic_error("carrier type without a constructor");
}

} // namespace slides
