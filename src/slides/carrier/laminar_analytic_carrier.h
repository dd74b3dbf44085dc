// LaminarAnalyticCarrier: what the closed-form laminar carriers share (carrier/plane_poiseuille.h
// and the unsteady ones of carrier/unsteady_analytic_carrier.h): k = ε = 0 and one gas
// temperature.
//
//     carrier { type planePoiseuille; ... }   or   carrier { type taylorGreenVortex; ... }
#pragma once

#include "slides/carrier/carrier_field.h"

#include <algorithm>

namespace slides {

class LaminarAnalyticCarrier : public CarrierField {
protected:
    explicit LaminarAnalyticCarrier(double temperature) : temperature_(temperature) {}

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
