// NoGas: the carrier of a scene without gas (carrier.type none), a DEM scene of gravity and
// contacts: zero velocity everywhere and no other field. The stepper flies its particles
// ballistically (run/stepper.cpp).
//
//     carrier { type none; }
#pragma once

#include "slides/carrier/carrier_field.h"

#include <algorithm>

namespace slides {

class NoGas final : public CarrierField {
public:
    void sample(std::span<const Vec3> points, double, CarrierNeeds needs,
                CarrierSample& out) const override {
        out.resize(points.size(), needs);
        std::fill(out.velocity.begin(), out.velocity.end(), Vec3::Zero());
        std::fill(out.velocityGradient.begin(), out.velocityGradient.end(), Mat3::Zero());
    }
    CarrierNeeds provides() const override { return {}; }
    std::string describe() const override { return "none (no carrier gas)"; }
};

} // namespace slides
