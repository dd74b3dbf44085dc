// makeCarrier: the carrier field named by `carrier.type` (one table, one switch).
//
//     carrier { type analyticJet; analyticJetCoeffs { nozzleVelocity 25; } }
//
// How to add a carrier: an enumerator in CarrierType (carrier/carrier_settings.h), its name in the
// key table (config/scene_keys.cpp, carrier.type) with a <name>Coeffs dictionary, and its case
// here.
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/carrier/carrier_settings.h"

#include <filesystem>
#include <memory>

namespace slides {

/// The carrier of carrier.type about the nozzle. The analytic jets carry k, ε (and T at
/// gasTemperature) only when needs ask for turbulence or temperature; a foamField reads the case
/// in caseDirectory and must hold the nozzle's centre (InputError naming dictionaryFile).
std::unique_ptr<CarrierField> makeCarrier(const CarrierSettings& carrier, const JetNozzle& nozzle,
                                          double gasTemperature, CarrierNeeds needs,
                                          const std::filesystem::path& caseDirectory,
                                          const std::filesystem::path& dictionaryFile);

} // namespace slides
