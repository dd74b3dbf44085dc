// UnsteadyAnalyticCarrier: what the closed-form unsteady carriers share (carrier/oscillating_gas.h,
// carrier/taylor_green_vortex.h): laminar gas (k = ε = 0) at one temperature, with U, ∇U and
// ∂U/∂t in closed form, for the unsteady terms of Eq. 3.3 of the reference.
//
//     carrier { type oscillatingGas; ... }   or   carrier { type taylorGreenVortex; ... }
#pragma once

#include "slides/carrier/carrier_field.h"

#include <algorithm>

namespace slides {

class UnsteadyAnalyticCarrier : public CarrierField {
public:
    bool steady() const final { return false; }
    CarrierNeeds provides() const final {
        return {.velocityGradient = true, .temperature = true, .timeDerivative = true};
    }

protected:
    explicit UnsteadyAnalyticCarrier(double temperature) : temperature_(temperature) {}

    /// k = ε = 0 and the gas temperature, where out holds them.
    void fillLaminarScalars(CarrierSample& out) const {
        std::fill(out.turbulentKineticEnergy.begin(), out.turbulentKineticEnergy.end(), 0.0);
        std::fill(out.dissipationRate.begin(), out.dissipationRate.end(), 0.0);
        std::fill(out.temperature.begin(), out.temperature.end(), temperature_);
    }

private:
    double temperature_; ///< [K]
};

} // namespace slides
