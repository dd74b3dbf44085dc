// Carriers with turbulence and temperature for the dispersion and heat-transfer tests:
// homogeneous isotropic turbulence at rest (constant k, ε) in gas of uniform temperature.
#pragma once

#include "slides/carrier/carrier_field.h"

#include <algorithm>
#include <string>

namespace slides::test {

/// U = 0 (or a uniform velocity), constant k, ε and T everywhere.
class UniformTurbulentGas : public CarrierField {
public:
    UniformTurbulentGas(double k, double epsilon, double temperature, Vec3 velocity = Vec3::Zero())
        : k_(k), epsilon_(epsilon), temperature_(temperature), velocity_(std::move(velocity)) {}
    void sample(std::span<const Vec3> points, double, CarrierNeeds needs,
                CarrierSample& out) const override {
        out.resize(points.size(), needs);
        std::fill(out.velocity.begin(), out.velocity.end(), velocity_);
        for (auto& gradient : out.velocityGradient) gradient.setZero();
        std::fill(out.turbulentKineticEnergy.begin(), out.turbulentKineticEnergy.end(), k_);
        std::fill(out.dissipationRate.begin(), out.dissipationRate.end(), epsilon_);
        std::fill(out.temperature.begin(), out.temperature.end(), temperature_);
    }
    std::string describe() const override { return "uniform turbulent gas"; }

private:
    double k_, epsilon_, temperature_;
    Vec3 velocity_;
};

} // namespace slides::test
