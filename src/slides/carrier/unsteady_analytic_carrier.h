// UnsteadyAnalyticCarrier: what the closed-form unsteady carriers share (carrier/oscillating_gas.h,
// carrier/taylor_green_vortex.h): laminar gas (k = ε = 0) at one temperature, with U, ∇U, ∂U/∂t
// and ∇²U in closed form, for the unsteady terms of Eq. 3.3 of the reference and the Faxén terms
// of Eq. 3.2.
//
//     carrier { type oscillatingGas; ... }   or   carrier { type taylorGreenVortex; ... }
#pragma once

#include "slides/carrier/laminar_analytic_carrier.h"

namespace slides {

class UnsteadyAnalyticCarrier : public LaminarAnalyticCarrier {
public:
    bool steady() const final { return false; }
    CarrierNeeds provides() const final {
        return {.velocityGradient = true,
                .temperature = true,
                .timeDerivative = true,
                .velocityLaplacian = true};
    }

protected:
    using LaminarAnalyticCarrier::LaminarAnalyticCarrier;
};

} // namespace slides
