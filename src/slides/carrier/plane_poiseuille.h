// PlanePoiseuille: steady laminar flow between plane walls at y = ±h, along x,
//   u = U (1 − y²/h²) e_x,   ∂u/∂y = −2Uy/h²,   ∇²u = −2U/h² e_x,
// the quadratic flow in which the Faxén terms of Eq. 3.2 (physics/faxen.h; Maxey & Riley 1983)
// have a closed-form effect: a particle under Stokes drag alone lags the local gas by U R²/(3h²).
// The parabola is the field everywhere: the walls are surfaces of the case, not of the carrier.
//
//     carrier { type planePoiseuille; planePoiseuilleCoeffs { centrelineVelocity 1; halfWidth 0.01;
//     } }
#pragma once

#include "slides/carrier/laminar_analytic_carrier.h"

namespace slides {

class PlanePoiseuille final : public LaminarAnalyticCarrier {
public:
    /// centreline velocity U [m/s], half-width h [m], gas temperature [K].
    PlanePoiseuille(double centrelineVelocity, double halfWidth, double temperature)
        : LaminarAnalyticCarrier(temperature), centrelineVelocity_(centrelineVelocity),
          halfWidth_(halfWidth) {}

    void sample(std::span<const Vec3> points, double time, CarrierNeeds needs,
                CarrierSample& out) const override;
    CarrierNeeds provides() const override {
        return {.velocityGradient = true, .temperature = true, .velocityLaplacian = true};
    }
    std::string describe() const override;

private:
    double centrelineVelocity_, halfWidth_;
};

} // namespace slides
