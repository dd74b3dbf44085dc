// makeCarrier: the carrier field named by the scene's `carrier.type` (one table, one switch).
//
// How to add a carrier: an enumerator in CarrierType (config/scene.h), its name in the key
// table (config/scene_keys.cpp, carrier.type) with a <name>Coeffs dictionary, and its case here.
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/config/scene.h"

#include <memory>

namespace slides {

std::unique_ptr<CarrierField> makeCarrier(const Scene& scene);

} // namespace slides
