#include "slides/analysis/pilot_paths.h"

#include "slides/analysis/physics_terms.h"
#include "slides/run/stepper.h"

#include <algorithm>
#include <unordered_map>

namespace slides {

namespace {

/// The scene of the pilot: its first particles, all at the start, drag and body force only,
/// every surface a sink.
Scene pilotScene(const Scene& scene, double dt) {
    Scene pilot = scene;
    pilot.injection.mode = InjectionMode::allAtStart;
    // Several injectors: an equal share of the pilot from each, its first particles (their ids
    // and draws those of the run), all at the start.
    const long share =
        std::max(1L, pilotParticles / std::max(1L, static_cast<long>(scene.injectors.size())));
    pilot.particles.count = 0;
    for (InjectorSettings& injector : pilot.injectors) {
        injector.count = std::min(injector.count, share);
        injector.injection.mode = InjectionMode::allAtStart;
        injector.startTime = 0;
        if (injector.givesRows()) injector.rows.resize(static_cast<std::size_t>(injector.count));
        for (ParticleRow& row : injector.rows) row.time = 0;
        pilot.particles.count += injector.count;
    }
    if (pilot.injectors.empty())
        pilot.particles.count = std::min(scene.particles.count, pilotParticles);
    // Its particles keep their species: the ids of its shorter blocks tell them.
    if (!pilot.particles.alike()) pilot.particles.injectorIds = injectorIdsOf(pilot.injectors);
    for (const auto& row : physicsTermNames()) setTerm(pilot, row.value, false);
    pilot.physics.automaticTerms.clear();
    for (Surface& surface : pilot.surfaces) surface.interaction = SurfaceInteraction::absorb;
    pilot.time.dt = dt;
    pilot.time.stopWhenAllDone = true;
    return pilot;
}

} // namespace

PilotSummary tracePilotPaths(const Scene& scene, const CarrierField& carrier, double dt,
                             const std::function<void(const PilotStep&)>& visit) {
    const Scene pilot = pilotScene(scene, dt);
    Stepper stepper(pilot, carrier);
    CarrierNeeds needs = carrier.provides();
    needs.velocityGradient = true;
    needs.timeDerivative = !carrier.steady();

    PilotStep step;
    CarrierSample gas;
    std::vector<std::int32_t> locations;
    std::unordered_map<ParticleId, Vec3> previousVelocity;
    PilotSummary summary{pilot.particles.count, 0, dt, 0};
    while (!stepper.finished() && summary.steps < pilotMaxSteps) {
        const double before = stepper.time();
        stepper.step();
        ++summary.steps;
        const ParticleCloud& cloud = stepper.cloud();
        step.time = stepper.time();
        step.h = step.time - before;
        locations = cloud.carrierLocation;
        locations.resize(cloud.size(), -1);
        if (carrier.keepsLocations())
            carrier.sampleFrom(cloud.position, locations, step.time, needs, gas);
        else
            carrier.sample(cloud.position, step.time, needs, gas);

        step.points.resize(cloud.size());
        std::unordered_map<ParticleId, Vec3> velocities;
        for (std::size_t i = 0; i < cloud.size(); ++i) {
            PathPoint& point = step.points[i];
            point.id = cloud.id[i];
            point.radius = cloud.radius[i];
            point.position = cloud.position[i];
            point.velocity = cloud.velocity[i];
            const auto previous = previousVelocity.find(point.id);
            point.acceleration = previous == previousVelocity.end()
                                     ? Vec3::Zero()
                                     : Vec3((point.velocity - previous->second) / step.h);
            point.gasVelocity = gas.velocity[i];
            point.gasVelocityGradient = gas.velocityGradient[i];
            point.gasTimeDerivative =
                needs.timeDerivative ? gas.velocityTimeDerivative[i] : Vec3::Zero();
            point.turbulentEnergy = needs.turbulence ? gas.turbulentKineticEnergy[i] : 0;
            point.dissipationRate = needs.turbulence ? gas.dissipationRate[i] : 0;
            point.gasTemperature = needs.temperature ? gas.temperature[i] : scene.fluid.temperature;
            point.resolutionLength = carrier.resolutionLength(locations[i]);
            velocities.emplace(point.id, point.velocity);
        }
        step.ended.clear();
        for (const auto& [id, velocity] : previousVelocity)
            if (!velocities.contains(id)) step.ended.push_back(id);
        std::sort(step.ended.begin(), step.ended.end());
        previousVelocity = std::move(velocities);
        visit(step);
    }
    summary.unfinished = static_cast<long>(stepper.cloud().size());
    return summary;
}

} // namespace slides
