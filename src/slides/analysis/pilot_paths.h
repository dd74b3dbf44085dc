// Pilot paths: the first particles of a scene traced with drag, gravity and buoyancy only, for
// the scene analysis (analysis/scene_analysis.h) to estimate the other terms along them.
//
// The pilot is the scene's own stepper on a copy of the scene: the first pilotParticles
// particles (the same draws as in the run: random numbers are keyed by particle id), all
// injected at the start (the carriers are steady), every optional term off, every surface a
// sink, so each path ends where the particle first touches a surface or leaves the domain.
// After each step the carrier is sampled at every particle with all it provides.
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/config/scene.h"
#include "slides/core/particle_cloud.h"

#include <functional>
#include <vector>

namespace slides {

/// A pilot particle after one step, and the gas where it is.
struct PathPoint {
    ParticleId id = 0;
    double radius = 0;           ///< [m]
    Vec3 position;               ///< [m]
    Vec3 velocity;               ///< [m/s]
    Vec3 acceleration;           ///< dv/dt over the step [m/s²]
    Vec3 gasVelocity;            ///< U [m/s]
    Mat3 gasVelocityGradient;    ///< dU_i/dx_j [1/s]
    Vec3 gasTimeDerivative;      ///< ∂U/∂t [m/s²], 0 for a steady carrier
    double turbulentEnergy = 0;  ///< k [m²/s²], 0 when the carrier has none
    double dissipationRate = 0;  ///< ε [m²/s³]
    double gasTemperature = 0;   ///< T [K]: the carrier's, else fluid.temperature
    double resolutionLength = 0; ///< the carrier's cell size there [m] (CarrierField)
};

/// One pilot step: the time after it, its length, the particles in flight and those whose
/// paths ended in it.
struct PilotStep {
    double time = 0;
    double h = 0;
    std::vector<PathPoint> points;
    std::vector<ParticleId> ended;
};

struct PilotSummary {
    long particles = 0;
    long steps = 0;
    double dt = 0;
    long unfinished = 0; ///< still in flight when the pilot stopped (endTime or maxSteps)
};

inline constexpr long pilotParticles = 128;
inline constexpr long pilotMaxSteps = 20000;

/// Traces the pilot with time step dt, calling visit after every step.
PilotSummary tracePilotPaths(const Scene& scene, const CarrierField& carrier, double dt,
                             const std::function<void(const PilotStep&)>& visit);

} // namespace slides
