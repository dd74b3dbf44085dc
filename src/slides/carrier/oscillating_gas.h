// OscillatingGas: a uniform gas oscillating in time, u(t) = U sin ωt, ω = 2πf, the unsteady
// carrier whose Maxey–Riley response has a closed form (Stokes drag, added mass, pressure
// gradient and Basset history: the amplitude ratio and phase of Eq. 3.3 by the Fourier
// transform; Maxey & Riley 1983, Phys. Fluids 26:883; Coimbra & Rangel 1998, J. Fluid Mech.
// 370:53). ∇U = 0, so DU/Dt = ∂U/∂t = U ω cos ωt.
//
//     carrier { type oscillatingGas; oscillatingGasCoeffs { amplitude (1 0 0); frequency 50; } }
#pragma once

#include "slides/carrier/unsteady_analytic_carrier.h"

#include <numbers>

namespace slides {

class OscillatingGas final : public UnsteadyAnalyticCarrier {
public:
    /// amplitude U [m/s], frequency f [Hz], the gas temperature [K] for heating.
    OscillatingGas(const Vec3& amplitude, double frequency, double temperature)
        : UnsteadyAnalyticCarrier(temperature), amplitude_(amplitude),
          angularFrequency_(2 * std::numbers::pi * frequency) {}

    void sample(std::span<const Vec3> points, double time, CarrierNeeds needs,
                CarrierSample& out) const override;
    std::string describe() const override;

    /// U sin ωt [m/s].
    Vec3 velocity(double time) const;
    /// ∂U/∂t = U ω cos ωt [m/s²].
    Vec3 acceleration(double time) const;

private:
    Vec3 amplitude_;
    double angularFrequency_;
};

} // namespace slides
