// Scene: the typed, validated configuration of one run, built from constant/slidesProperties.
//
// Every field is in SI units and already checked (config/scene_reader.cpp); the key table that
// documents each dictionary entry is config/scene_keys.cpp (`slides-track --list-keys`).
#pragma once

#include "slides/analysis/physics_terms.h"
#include "slides/carrier/carrier_field.h"
#include "slides/carrier/foam_interpolation.h"
#include "slides/carrier/jet_frame.h"
#include "slides/carrier/jet_scalars.h"
#include "slides/collide/collision_settings.h"
#include "slides/core/vector.h"
#include "slides/integrate/integrator.h"
#include "slides/io/particle_fields.h"
#include "slides/physics/adhesion.h"
#include "slides/physics/contact_pair.h"
#include "slides/physics/dispersion.h"
#include "slides/physics/drag.h"
#include "slides/physics/heat_transfer.h"
#include "slides/physics/history_integrator.h"
#include "slides/physics/lift.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace slides {

struct FluidSettings {
    double density = 0;             ///< ρf [kg/m³]
    double kinematicViscosity = 0;  ///< ν [m²/s]
    double temperature = 0;         ///< [K]
    double thermalConductivity = 0; ///< K_f [W/(m K)], heat transfer
    double specificHeat = 0;        ///< c_f [J/(kg K)], heat transfer
};

enum class CarrierType { analyticJet, roundLaminarJet, foamField, none };

struct CarrierSettings {
    CarrierType type = CarrierType::analyticJet;
    JetGeometry profile = JetGeometry::axisymmetric; ///< analyticJet only
    double nozzleVelocity = 0;                       ///< U0 [m/s]
    double coreLength = 0;                           ///< unentrained core [m]
    double viscosity = 0; ///< ν that sets the spreading: effectiveViscosity or the fluid's
    std::optional<double> C1, C2, C3;        ///< Eq. 5.10/5.11 coefficients when given explicitly
    std::optional<JetTurbulence> turbulence; ///< k, ε of the analytic jets (none: laminar)
    // foamField only:
    std::string foamTime = "latestTime"; ///< time directory: latestTime or a time value
    FoamInterpolation interpolation = FoamInterpolation::cellPoint;
    double latticeSpacing = 0; ///< interpolation lattice: node spacing [m], 0: extent/100
};

enum class RadiusDistributionKind { fixed, normal, logNormal };

struct RadiusDistribution {
    RadiusDistributionKind kind = RadiusDistributionKind::fixed;
    double value = 0;                      ///< fixed radius [m]
    double mean = 0;                       ///< normal: mean radius [m]
    double standardDeviation = 0;          ///< normal [m]
    double median = 0;                     ///< logNormal: median radius [m]
    double geometricStandardDeviation = 1; ///< logNormal: e^σ of ln R (≥ 1)
    double minimum = 0;                    ///< draws below are redrawn [m]
    double maximum = 0;                    ///< draws above are redrawn [m]
    double meanRadius() const;             ///< expected value of the (untruncated) distribution [m]
};

struct ParticleSettings {
    long count = 0;
    double density = 0; ///< ρp [kg/m³]
    RadiusDistribution radius;
    MaterialSettings material;
    double specificHeat = 0;         ///< c_p [J/(kg K)], heat transfer
    double thermalConductivity = 0;  ///< K_p [W/(m K)], for the Biot number; 0: not given
    double injectionTemperature = 0; ///< θ at injection [K], heat transfer
};

enum class InjectionMode { rate, allAtStart, lattice };

struct InjectionSettings {
    InjectionMode mode = InjectionMode::rate;
    double rate = 0;           ///< particles per second (mode rate)
    double crossSpanSpeed = 0; ///< magnitude of the random velocity ⟂ axis [m/s]
    std::uint64_t seed = 1;
    // Mode lattice: a simple cubic lattice of sites, filled in order x, y, z.
    Vec3 latticeOrigin = Vec3::Zero(); ///< lower corner of the first cell [m]
    double latticeSpacing = 0;         ///< a [m]
    std::array<int, 3> latticeSites{}; ///< per axis
    double latticeVelocitySpread = 0;  ///< uniform in [−spread, spread] per component [m/s]
};

struct PhysicsSettings {
    DragModel drag = DragModel::haiderLevenspiel;
    Vec3 gravity = Vec3::Zero(); ///< [m/s²]
    bool buoyancy = true;
    // Unsteady terms (integrate/maxey_riley.h); all off by default.
    HistoryModel history = HistoryModel::none;
    double historyAccuracy = 1e-3; ///< relative error target of the history kernel's tail
    bool addedMass = false;
    bool pressureGradient = false;
    LiftModel lift = LiftModel::none;
    bool spin = false;
    bool spinHistory = false; ///< the unsteady torque of Eq. 3.19 (needs spin)
    DispersionModel dispersion = DispersionModel::none; ///< physics/dispersion.h
    DispersionConstants dispersionConstants;
    HeatTransferModel heatTransfer = HeatTransferModel::none; ///< physics/heat_transfer.h
    /// Terms left to the scene analysis (`auto`), off until it turns them on.
    std::vector<AutomaticTerm> automaticTerms;
    /// Largest estimated effect of a term that auto turns off (analysis/scene_analysis.h).
    double autoThreshold = 0.01;

    /// Whether any unsteady term is on: then the Maxey–Riley step replaces the integrator.
    bool unsteadyForces() const {
        return history != HistoryModel::none || addedMass || pressureGradient ||
               lift != LiftModel::none || spin;
    }
};

struct TimeSettings {
    double dt = 0;               ///< [s]; 0: the scene analysis chooses it
    double endTime = 0;          ///< [s]; the run also stops earlier when stopWhenAllDone
    bool stopWhenAllDone = true; ///< stop once every particle has arrived or escaped
    Integrator integrator = Integrator::exponentialMidpoint;
};

/// A surface: a sink, a wall or a deposition target (collide/collision_settings.h) — a plane
/// of the dictionary, or a wall patch of the OpenFOAM mesh (surfaces/patch_wall.h).
struct Surface {
    std::string name;
    /// The plane; for a patch, its mean plane (area-weighted centroid and normal), which the
    /// deposit's metrics and map use (surfaces/patch_wall.h, placePatchSurfaces).
    Vec3 point = Vec3::Zero();
    Vec3 normal = Vec3::UnitX(); ///< unit, pointing into the gas side
    MaterialSettings material;
    SurfaceInteraction interaction = SurfaceInteraction::absorb;
    std::string patch; ///< the mesh patch it is; empty for a plane
};

struct OutputSettings {
    double interval = 0;                               ///< [s] between particle frames
    std::array<int, 3> carrierResolution{};            ///< lattice points of carrier.vti per axis
    ParticleFieldSet fields = ParticleFieldSet::all(); ///< point arrays of each frame
    bool hdf5 = true; ///< also particles.h5 + particles.xmf (io/hdf5_particles.h)
};

struct Scene {
    std::filesystem::path caseDirectory;
    std::filesystem::path dictionaryFile;
    FluidSettings fluid;
    JetNozzle nozzle;
    CarrierSettings carrier;
    ParticleSettings particles;
    InjectionSettings injection;
    PhysicsSettings physics;
    TimeSettings time;
    CollisionSettings collisions;
    AdhesionSettings deposition; ///< adhesion of surfaces whose interaction is deposit
    std::vector<Surface> surfaces;
    Box domain;                     ///< particles leaving this box have escaped
    bool domainFromCarrier = false; ///< no domain given: the carrier's bounds (a mesh) set it
    OutputSettings output;
};

/// Whether the particles carry a spin ω: physics.spin, or contacts with friction (collisions,
/// surfaces that rebound or deposit) that change it.
inline bool tracksSpin(const Scene& scene) {
    return scene.physics.spin || scene.collisions.model != CollisionModel::none ||
           std::any_of(scene.surfaces.begin(), scene.surfaces.end(), [](const Surface& s) {
               return s.interaction != SurfaceInteraction::absorb;
           });
}

} // namespace slides
