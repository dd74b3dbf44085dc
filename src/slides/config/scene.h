// Scene: the typed, validated configuration of one run, built from constant/slidesProperties:
// the settings each stage owns (carrier/carrier_settings.h, integrate/injection_settings.h,
// physics/physics_settings.h, collide/collision_settings.h, surfaces/surface_settings.h,
// integrate/time_settings.h, io/output_settings.h), assembled by config/.
//
// Every field is in SI units and already checked (config/scene_reader.cpp); the key table that
// documents each dictionary entry is config/scene_keys.cpp (`slides-track --list-keys`).
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/carrier/carrier_settings.h"
#include "slides/carrier/jet_frame.h"
#include "slides/collide/collision_settings.h"
#include "slides/core/vector.h"
#include "slides/integrate/injection_settings.h"
#include "slides/integrate/time_settings.h"
#include "slides/io/output_settings.h"
#include "slides/physics/adhesion.h"
#include "slides/physics/physics_settings.h"
#include "slides/surfaces/surface_settings.h"

#include <filesystem>
#include <vector>

namespace slides {

struct Scene {
    std::filesystem::path caseDirectory;
    std::filesystem::path dictionaryFile;
    FluidSettings fluid;
    JetNozzle nozzle;
    CarrierSettings carrier;
    ParticleSettings particles;
    InjectionSettings injection;
    /// The injectors of `injectors {}`; empty: the one of nozzle + injection (injectorsOf).
    std::vector<InjectorSettings> injectors;
    PhysicsSettings physics;
    TimeSettings time;
    CollisionSettings collisions;
    AdhesionSettings deposition; ///< adhesion of surfaces whose interaction is deposit
    std::vector<Surface> surfaces;
    Box domain;                     ///< particles leaving this box have escaped
    bool domainFromCarrier = false; ///< no domain given: the carrier's bounds (a mesh) set it
    OutputSettings output;
};

/// The run's injectors: those listed, or the one that nozzle + injection + particles describe.
inline std::vector<InjectorSettings> injectorsOf(const Scene& scene) {
    if (!scene.injectors.empty()) return scene.injectors;
    return {singleInjector(scene.injection, scene.nozzle, scene.particles)};
}

/// The names and first particle ids of the injectors of `injectors {}` (empty without).
inline std::vector<std::string> injectorNames(const Scene& scene) {
    std::vector<std::string> names;
    for (const InjectorSettings& injector : scene.injectors) names.push_back(injector.name);
    return names;
}
inline InjectorIds injectorIds(const Scene& scene) { return injectorIdsOf(scene.injectors); }

/// Whether the particles carry a spin ω (surfaces/surface_settings.h).
inline bool tracksSpin(const Scene& scene) {
    return tracksSpin(scene.physics.spin, scene.collisions, scene.surfaces);
}

} // namespace slides
