#include "slides/carrier/make_carrier.h"

#include "slides/carrier/analytic_jet.h"
#include "slides/carrier/foam_carrier.h"
#include "slides/carrier/jet_scalars.h"
#include "slides/carrier/no_gas.h"
#include "slides/carrier/oscillating_gas.h"
#include "slides/carrier/plane_poiseuille.h"
#include "slides/carrier/pulsed_jet.h"
#include "slides/carrier/round_laminar_jet.h"
#include "slides/carrier/taylor_green_vortex.h"
#include "slides/core/error.h"

#include <array>
#include <sstream>

namespace slides {

namespace {

/// Particles injected outside the mesh would escape at once: refuse such a case.
void requireNozzleInMesh(const JetNozzle& nozzle, const FoamCarrier& carrier,
                         const std::filesystem::path& dictionaryFile) {
    const std::array<Vec3, 1> centre{nozzle.centre};
    std::array<std::int32_t, 1> location{-1};
    CarrierSample sample;
    carrier.sampleFrom(centre, location, 0.0, CarrierNeeds{}, sample);
    if (location[0] < -1) {
        const Vec3& x = nozzle.centre;
        std::ostringstream message;
        message << "(" << x.x() << " " << x.y() << " " << x.z()
                << ") lies outside the OpenFOAM mesh: particles would be injected outside it";
        throw InputError(dictionaryFile.string(), 0, "nozzle.centre", message.str());
    }
}

} // namespace

std::unique_ptr<CarrierField> makeCarrier(const CarrierSettings& carrier, const JetNozzle& nozzle,
                                          double gasTemperature, CarrierNeeds needs,
                                          const std::filesystem::path& caseDirectory,
                                          const std::filesystem::path& dictionaryFile) {
    // k, ε and T only for models that ask for them; otherwise the bare jet.
    const bool needsScalars = needs.turbulence || needs.temperature;
    const auto withScalars = [&]<typename Jet>(std::unique_ptr<Jet> jet) {
        if (!needsScalars) return std::unique_ptr<CarrierField>(std::move(jet));
        return std::unique_ptr<CarrierField>(
            std::make_unique<JetScalars<Jet>>(std::move(jet), carrier.turbulence, gasTemperature));
    };
    // A pulsed nozzle wraps the steady jet; without one the steady jet itself, bit for bit.
    const auto withPulsation = [&]<typename Jet>(std::unique_ptr<Jet> jet) {
        if (!carrier.pulsation) return withScalars(std::move(jet));
        return withScalars(std::make_unique<PulsedJet<Jet>>(std::move(jet), *carrier.pulsation));
    };
    switch (carrier.type) {
    case CarrierType::none: return std::make_unique<NoGas>();
    case CarrierType::analyticJet:
        return withPulsation(std::make_unique<AnalyticJet>(
            nozzle,
            AnalyticJetParameters{carrier.profile, carrier.nozzleVelocity, carrier.viscosity,
                                  carrier.coreLength, carrier.C1, carrier.C2, carrier.C3}));
    case CarrierType::roundLaminarJet:
        return withPulsation(std::make_unique<RoundLaminarJet>(
            nozzle, RoundLaminarJetParameters{carrier.nozzleVelocity, carrier.viscosity,
                                              carrier.coreLength}));
    case CarrierType::oscillatingGas:
        return std::make_unique<OscillatingGas>(carrier.oscillationAmplitude,
                                                carrier.oscillationFrequency, gasTemperature);
    case CarrierType::taylorGreenVortex:
        return std::make_unique<TaylorGreenVortex>(carrier.vortexVelocity, carrier.vortexWavelength,
                                                   carrier.viscosity, gasTemperature);
    case CarrierType::planePoiseuille:
        return std::make_unique<PlanePoiseuille>(carrier.centrelineVelocity,
                                                 carrier.channelHalfWidth, gasTemperature);
    case CarrierType::foamField: {
        auto field = std::make_unique<FoamCarrier>(
            caseDirectory, FoamCarrierSettings{carrier.foamTime, carrier.interpolation,
                                               carrier.latticeSpacing, carrier.foamSeries});
        requireNozzleInMesh(nozzle, *field, dictionaryFile);
        return field;
    }
    }
    throw std::logic_error("carrier type without a constructor");
}

} // namespace slides
