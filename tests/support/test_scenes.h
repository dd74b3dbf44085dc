// Scenes and carrier fields for tests, built in code rather than read from a dictionary.
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/config/scene.h"
#include "slides/run/resolved_scene.h"

#include <memory>
#include <string>

namespace slides::test {

/// One particle (R = 50 µm, ρp = 2500) at rest at the origin in air-like gas, no gravity,
/// no surfaces, a domain large enough never to be left.
inline Scene singleParticleScene() {
    Scene scene;
    scene.fluid = {1.2, 1.5e-5, 293.15};
    scene.nozzle.radius = 1e-15; // a point source: exact solutions start at the centre
    scene.particles.count = 1;
    scene.particles.density = 2500;
    scene.particles.radius.kind = RadiusDistributionKind::fixed;
    scene.particles.radius.value = 50e-6;
    scene.injection.mode = InjectionMode::allAtStart;
    scene.physics.drag = DragModel::haiderLevenspiel;
    scene.physics.gravity = Vec3::Zero();
    scene.time.dt = 1e-3;
    scene.time.endTime = 1.0;
    scene.time.stopWhenAllDone = false;
    scene.domain = {Vec3::Constant(-1e6), Vec3::Constant(1e6)};
    scene.output.interval = 1.0;
    return scene;
}

using slides::carrierOf;

/// U = constant.
class UniformFlow : public CarrierField {
public:
    explicit UniformFlow(Vec3 velocity) : velocity_(std::move(velocity)) {}
    void sample(std::span<const Vec3> points, double, CarrierNeeds needs,
                CarrierSample& out) const override {
        out.resize(points.size(), needs);
        for (auto& u : out.velocity) u = velocity_;
        for (auto& gradient : out.velocityGradient) gradient.setZero();
    }
    std::string describe() const override { return "uniform flow"; }

private:
    Vec3 velocity_;
};

/// Plane stagnation-point flow plus a swirl, U = (−s x − w y, s y + w x, 0) + offset: smooth,
/// non-uniform and curved, so particle paths test the integrators' order.
class SwirlingStagnationFlow : public CarrierField {
public:
    SwirlingStagnationFlow(double strain, double swirl, Vec3 offset)
        : strain_(strain), swirl_(swirl), offset_(std::move(offset)) {}
    void sample(std::span<const Vec3> points, double, CarrierNeeds needs,
                CarrierSample& out) const override {
        out.resize(points.size(), needs);
        Mat3 gradient;
        gradient << -strain_, -swirl_, 0, swirl_, strain_, 0, 0, 0, 0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            out.velocity[i] = gradient * points[i] + offset_;
            if (needs.velocityGradient) out.velocityGradient[i] = gradient;
        }
    }
    std::string describe() const override { return "swirling stagnation flow"; }

private:
    double strain_, swirl_;
    Vec3 offset_;
};

/// U = Ω × x for t < switchOff, at rest after: vorticity 2Ω then 0.
class SwitchedVortex : public CarrierField {
public:
    SwitchedVortex(double rate, double switchOff) : rate_(rate), switchOff_(switchOff) {}
    void sample(std::span<const Vec3> points, double time, CarrierNeeds needs,
                CarrierSample& out) const override {
        out.resize(points.size(), needs);
        const double rate = time < switchOff_ ? rate_ : 0.0;
        Mat3 gradient;
        gradient << 0, -rate, 0, rate, 0, 0, 0, 0, 0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            out.velocity[i] = gradient * points[i];
            if (needs.velocityGradient) out.velocityGradient[i] = gradient;
        }
    }
    std::string describe() const override { return "switched vortex"; }

private:
    double rate_, switchOff_;
};

} // namespace slides::test
