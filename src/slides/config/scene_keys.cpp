#include "slides/config/scene_keys.h"

#include "slides/carrier/carrier_settings.h"
#include "slides/carrier/foam_interpolation.h"
#include "slides/collide/collision_settings.h"
#include "slides/integrate/injection_settings.h"
#include "slides/integrate/integrator.h"
#include "slides/io/particle_fields.h"
#include "slides/physics/adhesion.h"
#include "slides/physics/dispersion.h"
#include "slides/physics/drag.h"
#include "slides/physics/electromagnetic.h"
#include "slides/physics/heat_transfer.h"
#include "slides/physics/history_integrator.h"
#include "slides/physics/lift.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace slides {

namespace {

constexpr double noMinimum = -std::numeric_limits<double>::infinity();
constexpr double maximumGasSpeed = 1e4; // m/s, beyond any gas jet
constexpr double maximumRadius = 1;     // m, beyond any particle a jet carries

template <typename Table> std::vector<std::string> namesOf(const Table& table) {
    std::vector<std::string> names;
    for (const auto& entry : table) names.emplace_back(entry.name);
    return names;
}

/// The names of a family whose term the scene analysis may choose, then auto.
template <typename Table> std::vector<std::string> namesOrAuto(const Table& table) {
    std::vector<std::string> names = namesOf(table);
    names.emplace_back("auto");
    return names;
}

std::vector<KeyDeclaration> declareKeys() {
    using K = KeyKind;
    using R = KeyRange;
    // One declaration per row, read as the table it is.
    // clang-format off
    std::vector<KeyDeclaration> keys = {
        {"carrier", K::dictionary, "-", "", {}, R::any, "The carrier gas field."},
        {"carrier.type", K::word, "-", "analyticJet",
         namesOf(carrierTypeNames()), R::any,
         "analyticJet: sech² jet of Eq. 5.10/5.11; roundLaminarJet: Schlichting's exact round "
         "laminar jet; foamField: the OpenFOAM fields of this case (U; k, epsilon, T if present); "
         "none: no gas (a DEM scene: gravity and contacts only, time.dt given); oscillatingGas: "
         "uniform gas u = U sin 2πft; taylorGreenVortex: the decaying Taylor–Green vortex (both "
         "unsteady, with closed forms); planePoiseuille: steady channel flow u = U(1 − y²/h²) "
         "along x."},
        {"carrier.analyticJetCoeffs", K::dictionary, "-", "-", {}, R::any,
         "Coefficients of the sech² jet (Eq. 5.10/5.11)."},
        {"carrier.analyticJetCoeffs.profile", K::word, "-", "axisymmetric",
         namesOf(jetGeometryNames()), R::any,
         "planar: Bickley's plane jet across nozzle.crossSpanDirection; axisymmetric: the same "
         "profile with y replaced by the radius (the reference's 3-D use)."},
        {"carrier.analyticJetCoeffs.nozzleVelocity", K::scalar, "m/s", "", {}, R::positive,
         "Exit velocity U0; the virtual origin puts U0 on the centreline at the core end.",
         noMinimum, maximumGasSpeed},
        {"carrier.analyticJetCoeffs.coreLength", K::scalar, "m", "0", {}, R::nonNegative,
         "Length of the unentrained core after the nozzle (profile frozen, no entrainment)."},
        {"carrier.analyticJetCoeffs.effectiveViscosity", K::scalar, "m^2/s", "-", {},
         R::positive,
         "Viscosity that sets the spreading rate (e.g. an eddy viscosity for a turbulent jet); "
         "default fluid.kinematicViscosity."},
        {"carrier.analyticJetCoeffs.C1", K::scalar, "m^(4/3)/s", "-", {}, R::positive,
         "Eq. 5.10 amplitude; with C3, replaces the values derived from the nozzle."},
        {"carrier.analyticJetCoeffs.C2", K::scalar, "m^(5/3)/s", "-", {}, R::positive,
         "Eq. 5.11 amplitude; continuity fixes it to C1/(3 C3), so it may only repeat that."},
        {"carrier.analyticJetCoeffs.C3", K::scalar, "m^(-1/3)", "-", {}, R::positive,
         "Eq. 5.10 similarity scale; given together with C1."},
        {"carrier.analyticJetCoeffs.pulsation", K::dictionary, "-", "-", {}, R::any,
         "A pulsed nozzle, U0(t) = U0 (1 + A sin 2πft), the pulse carried downstream at the mean "
         "jet's centreline speed (a kinematic model, carrier/pulsed_jet.h); without it the "
         "jet is steady."},
        {"carrier.analyticJetCoeffs.pulsation.amplitude", K::scalar, "-", "0", {}, R::nonNegative,
         "Relative amplitude A of the nozzle velocity, below 1; 0: the steady jet."},
        {"carrier.analyticJetCoeffs.pulsation.frequency", K::scalar, "Hz", "-", {}, R::positive,
         "Pulsation frequency f (required when amplitude > 0)."},
        {"carrier.roundLaminarJetCoeffs", K::dictionary, "-", "-", {}, R::any,
         "Coefficients of Schlichting's round laminar jet."},
        {"carrier.roundLaminarJetCoeffs.nozzleVelocity", K::scalar, "m/s", "", {}, R::positive,
         "Exit velocity U0 of the round nozzle.", noMinimum, maximumGasSpeed},
        {"carrier.roundLaminarJetCoeffs.coreLength", K::scalar, "m", "0", {}, R::nonNegative,
         "Length of the unentrained core after the nozzle."},
        {"carrier.roundLaminarJetCoeffs.effectiveViscosity", K::scalar, "m^2/s", "-", {},
         R::positive, "Viscosity that sets the spreading rate; default fluid.kinematicViscosity."},
        {"carrier.roundLaminarJetCoeffs.pulsation", K::dictionary, "-", "-", {}, R::any,
         "A pulsed nozzle, U0(t) = U0 (1 + A sin 2πft), the pulse carried downstream at the mean "
         "jet's centreline speed (a kinematic model, carrier/pulsed_jet.h); without it the "
         "jet is steady."},
        {"carrier.roundLaminarJetCoeffs.pulsation.amplitude", K::scalar, "-", "0", {}, R::nonNegative,
         "Relative amplitude A of the nozzle velocity, below 1; 0: the steady jet."},
        {"carrier.roundLaminarJetCoeffs.pulsation.frequency", K::scalar, "Hz", "-", {}, R::positive,
         "Pulsation frequency f (required when amplitude > 0)."},
        {"carrier.foamFieldCoeffs", K::dictionary, "-", "-", {}, R::any,
         "OpenFOAM fields of the case: constant/polyMesh and one time directory."},
        {"carrier.foamFieldCoeffs.time", K::word, "-", "latestTime", {}, R::any,
         "Time directory: latestTime or a time value (the command line's --time overrides it)."},
        {"carrier.foamFieldCoeffs.interpolation", K::word, "-", "cellPoint",
         namesOf(foamInterpolationNames()), R::any,
         "cell: the cell's value; cellPoint: point values, linear within the cell's tetrahedra; "
         "lattice: cellPoint resampled once onto a lattice, then trilinear (fast)."},
        {"carrier.foamFieldCoeffs.latticeSpacing", K::scalar, "m", "0", {}, R::nonNegative,
         "Node spacing of the lattice scheme; 0: 1/100 of the mesh's largest extent."},
        {"carrier.oscillatingGasCoeffs", K::dictionary, "-", "-", {}, R::any,
         "Uniform oscillating gas u(t) = U sin 2πft (carrier/oscillating_gas.h)."},
        {"carrier.oscillatingGasCoeffs.amplitude", K::vector, "m/s", "", {}, R::any,
         "Velocity amplitude U."},
        {"carrier.oscillatingGasCoeffs.frequency", K::scalar, "Hz", "", {}, R::positive,
         "Frequency f."},
        {"carrier.taylorGreenVortexCoeffs", K::dictionary, "-", "-", {}, R::any,
         "Decaying Taylor–Green vortex in the x–y plane, ν = fluid.kinematicViscosity "
         "(carrier/taylor_green_vortex.h)."},
        {"carrier.taylorGreenVortexCoeffs.velocity", K::scalar, "m/s", "", {}, R::positive,
         "Initial velocity amplitude U.", noMinimum, maximumGasSpeed},
        {"carrier.taylorGreenVortexCoeffs.wavelength", K::scalar, "m", "", {}, R::positive,
         "Period L of the vortex cells in x and y (k = 2π/L)."},
        {"carrier.planePoiseuilleCoeffs", K::dictionary, "-", "-", {}, R::any,
         "Plane Poiseuille flow u = U(1 − y²/h²) e_x, the parabola everywhere (walls are "
         "surfaces of the case; carrier/plane_poiseuille.h)."},
        {"carrier.planePoiseuilleCoeffs.centrelineVelocity", K::scalar, "m/s", "", {},
         R::positive, "Centreline velocity U.", noMinimum, maximumGasSpeed},
        {"carrier.planePoiseuilleCoeffs.halfWidth", K::scalar, "m", "", {}, R::positive,
         "Half-width h: the walls' distance from the centreline y = 0; the parabola must stay "
         "within 10000 m/s over the domain."},
        {"carrier.foamFieldCoeffs.times", K::timeRange, "s", "-", {}, R::any,
         "A time series instead of one time directory: the written times from start to end "
         "(or all), U, k, epsilon, T linear in time between them on a fixed mesh "
         "(carrier/foam_series.h); run time 0 is the first level."},
        {"carrier.foamFieldCoeffs.cycle", K::scalar, "s", "-", {}, R::positive,
         "Period of a periodic series: run time t reads the series at t mod cycle, the first "
         "level following the last."},
        {"carrier.foamFieldCoeffs.readAhead", K::boolean, "-", "yes", {}, R::any,
         "Read the next level of a series on a background thread while the particles move "
         "(three levels held); no: read it when the run reaches it (two held)."},
        {"carrier.turbulence", K::dictionary, "-", "-", {}, R::any,
         "Turbulence of the analytic jets, k = 3/2 (I U)², ε = 0.09^(3/4) k^(3/2)/ℓ "
         "(carrier/jet_scalars.h); without it they are laminar (k = ε = 0)."},
        {"carrier.turbulence.scaling", K::word, "-", "uniform", namesOf(turbulenceScalingNames()), R::any,
         "uniform: U = nozzleVelocity, ℓ = lengthScale everywhere; jetLocal: U = local "
         "centreline velocity, ℓ = lengthScaleToHalfWidth × local half-width."},
        {"carrier.turbulence.intensity", K::scalar, "-", "", {}, R::positive,
         "Turbulence intensity I = u'/U."},
        {"carrier.turbulence.lengthScale", K::scalar, "m", "-", {}, R::positive,
         "Mixing length ℓ (scaling uniform)."},
        {"carrier.turbulence.lengthScaleToHalfWidth", K::scalar, "-", "-", {}, R::positive,
         "ℓ over the local jet half-width (scaling jetLocal)."},

        {"fluid", K::dictionary, "-", "-", {}, R::any,
         "Carrier gas properties (required unless carrier.type is none)."},
        {"fluid.density", K::scalar, "kg/m^3", "-", {}, R::positive, "Gas density ρf."},
        {"fluid.kinematicViscosity", K::scalar, "m^2/s", "-", {}, R::positive,
         "Gas kinematic viscosity ν."},
        {"fluid.temperature", K::scalar, "K", "293.15", {}, R::positive, "Gas temperature."},
        {"fluid.thermalConductivity", K::scalar, "W/(m K)", "0.0257", {}, R::positive,
         "Gas thermal conductivity K_f, for heat transfer (default: air at 293 K)."},
        {"fluid.specificHeat", K::scalar, "J/(kg K)", "1005", {}, R::positive,
         "Gas specific heat c_f, for the Prandtl number (default: air)."},

        {"nozzle", K::dictionary, "-", "-", {}, R::any,
         "The nozzle the gas and particles leave (required unless carrier.type is none and "
         "injection.mode lattice)."},
        {"nozzle.centre", K::vector, "m", "(0 0 0)", {}, R::any, "Centre of the nozzle exit."},
        {"nozzle.axis", K::vector, "-", "(1 0 0)", {}, R::any,
         "Jet direction (normalised on reading)."},
        {"nozzle.radius", K::scalar, "m", "-", {}, R::positive,
         "Nozzle radius (half-width of a planar slot)."},
        {"nozzle.crossSpanDirection", K::vector, "-", "(0 1 0)", {}, R::any,
         "Cross-span direction y of a planar jet; its part along the axis is removed."},

        {"particles", K::dictionary, "-", "", {}, R::any, "The particles."},
        {"particles.count", K::integer, "-", "-", {}, R::positive, "Number of particles; their arrays must fit in the machine's memory (run/run_limits.h). Required with injection; with injectors, their counts."},
        {"particles.density", K::scalar, "kg/m^3", "", {}, R::positive,
         "Particle material density ρp.", noMinimum, 1e5},
        {"particles.radiusDistribution", K::dictionary, "-", "", {}, R::any,
         "Particle radius distribution."},
        {"particles.radiusDistribution.type", K::word, "-", "fixed",
         namesOf(radiusDistributionNames()), R::any,
         "fixed: value; normal: mean, standardDeviation; logNormal: median, "
         "geometricStandardDeviation; rosinRammler: scale, spread; table: file."},
        {"particles.radiusDistribution.value", K::scalar, "m", "-", {}, R::positive,
         "Radius for type fixed.", noMinimum, maximumRadius},
        {"particles.radiusDistribution.mean", K::scalar, "m", "-", {}, R::positive,
         "Mean radius for type normal.", noMinimum, maximumRadius},
        {"particles.radiusDistribution.standardDeviation", K::scalar, "m", "-", {},
         R::nonNegative, "Standard deviation for type normal.", noMinimum, maximumRadius},
        {"particles.radiusDistribution.median", K::scalar, "m", "-", {}, R::positive,
         "Median radius for type logNormal.", noMinimum, maximumRadius},
        {"particles.radiusDistribution.geometricStandardDeviation", K::scalar, "-", "-", {},
         R::atLeastOne, "e^σ of ln R for type logNormal."},
        {"particles.radiusDistribution.minimum", K::scalar, "m", "0", {}, R::nonNegative,
         "Draws below this are redrawn.", noMinimum, maximumRadius},
        {"particles.radiusDistribution.maximum", K::scalar, "m", "-", {}, R::positive,
         "Draws above this are redrawn (default: no limit).", noMinimum, maximumRadius},
        {"particles.radiusDistribution.scale", K::scalar, "m", "-", {}, R::positive,
         "r̄ of type rosinRammler, F(r) = 1 − exp(−(r/r̄)^n): 63.2 % of the number (or mass) "
         "lies below it.", noMinimum, maximumRadius},
        {"particles.radiusDistribution.spread", K::scalar, "-", "-", {}, R::positive,
         "n of type rosinRammler (larger: narrower).", 0.1, 100},
        {"particles.radiusDistribution.file", K::word, "-", "-", {}, R::any,
         "Type table: a CSV with columns r (or d) [m] and F, the cumulative fraction below, "
         "rising from 0 to 1, linear in r between rows (integrate/size_distribution.h). "
         "Relative to the case directory."},
        {"particles.radiusDistribution.weighting", K::word, "-", "number",
         namesOf(sizeWeightingNames()), R::any,
         "What the distribution's parameters describe: number (a draw per particle) or mass "
         "(e.g. a mass-median radius; drawn as the number distribution f_m/r³; types fixed, "
         "logNormal, rosinRammler, table; rosinRammler needs minimum > 0)."},
        {"particles.material", K::dictionary, "-", "-", {}, R::any,
         "Elastic and adhesive properties (Table 5.2), for collision and deposition models."},
        {"particles.material.bulkModulus", K::scalar, "Pa", "-", {}, R::positive,
         "Bulk modulus."},
        {"particles.material.shearModulus", K::scalar, "Pa", "-", {}, R::positive,
         "Shear modulus."},
        {"particles.material.yieldStress", K::scalar, "Pa", "-", {}, R::positive,
         "Yield stress."},
        {"particles.material.surfaceEnergy", K::scalar, "J/m^2", "-", {}, R::positive,
         "Surface energy γ (Eq. 2.74)."},
        {"particles.specificHeat", K::scalar, "J/(kg K)", "-", {}, R::positive,
         "Particle specific heat c_p; required by physics.heatTransfer."},
        {"particles.thermalConductivity", K::scalar, "W/(m K)", "-", {}, R::positive,
         "Particle thermal conductivity K_p, for the Biot number of the scene analysis (the "
         "lumped temperature of Sec. 3.8 holds for Bi < 0.1)."},
        {"particles.injectionTemperature", K::scalar, "K", "-", {}, R::positive,
         "Particle temperature at injection; default fluid.temperature."},

        {"injection", K::dictionary, "-", "-", {}, R::any,
         "Particles start on the nozzle disc with the local gas velocity plus a random "
         "cross-span velocity (required without injectors; with injectors only seed)."},
        {"injection.mode", K::word, "-", "rate", namesOf(injectionModeNames()), R::any,
         "rate: one particle every 1/rate seconds; allAtStart: all at t = 0; lattice: all at "
         "t = 0 on the sites of a simple cubic lattice (latticeCoeffs)."},
        {"injection.rate", K::scalar, "1/s", "-", {}, R::positive,
         "Particles injected per second (mode rate)."},
        {"injection.crossSpanSpeed", K::scalar, "m/s", "0", {}, R::nonNegative,
         "Magnitude of the random velocity perpendicular to the axis, random direction."},
        {"injection.seed", K::integer, "-", "1", {}, R::nonNegative,
         "Seed of the counter-based random numbers."},
        {"injection.reinjectEscaped", K::boolean, "-", "no", {}, R::any,
         "Constant mass flow (Section 5.2.4): each particle that escapes (leaves the domain box "
         "or the mesh; not one that arrives at a surface) is replaced at the end of its step by "
         "a new one drawn as the injector's own, with a new id (integrate/injector_set.h). "
         "Modes rate and allAtStart; not in parallel runs."},
        {"injection.latticeCoeffs", K::dictionary, "-", "-", {}, R::any,
         "Injection mode lattice: particle k on site (i, j, l), k = i + n_x (j + n_y l), at "
         "origin + ((i + ½) a, (j + ½) a, (l + ½) a)."},
        {"injection.latticeCoeffs.origin", K::vector, "m", "(0 0 0)", {}, R::any,
         "Lower corner of the lattice's first cell."},
        {"injection.latticeCoeffs.spacing", K::scalar, "m", "", {}, R::positive,
         "Lattice spacing a."},
        {"injection.latticeCoeffs.sites", K::integerTriple, "-", "", {}, R::atLeastOne,
         "Sites per axis (n_x n_y n_z); particles.count must not exceed their product."},
        {"injection.latticeCoeffs.velocitySpread", K::scalar, "m/s", "0", {}, R::nonNegative,
         "Each velocity component gets a uniform random addition in [−spread, spread]."},

        {"injectors", K::dictionary, "-", "-", {}, R::any,
         "Several injectors instead of nozzle + injection (integrate/injection_settings.h); "
         "particle ids in blocks, injector by injector in the order written."},
        {"injectors.*", K::dictionary, "-", "-", {}, R::any, "One injector, named by its key."},
        {"injectors.*.model", K::word, "-", "disc", namesOf(injectionModelNames()), R::any,
         "disc: on the disc at the gas velocity plus crossSpanSpeed; cone: coneCoeffs' speed "
         "along a direction uniform over the cone's band of directions; file: the rows of file; "
         "patch: uniformly over a mesh patch's faces (patchCoeffs); "
         "ensemble: a packing at rest (ensembleCoeffs)."},
        {"injectors.*.centre", K::vector, "m", "(0 0 0)", {}, R::any,
         "Centre of the injector's disc (disc, cone)."},
        {"injectors.*.axis", K::vector, "-", "(1 0 0)", {}, R::any,
         "Its direction (normalised on reading)."},
        {"injectors.*.radius", K::scalar, "m", "0", {}, R::nonNegative,
         "Radius of its disc; 0: a point.", noMinimum, maximumRadius},
        {"injectors.*.crossSpanDirection", K::vector, "-", "(0 1 0)", {}, R::any,
         "A direction across the axis: the disc's azimuth 0 (its part along the axis removed)."},
        {"injectors.*.count", K::integer, "-", "-", {}, R::positive,
         "Particles it injects (disc, cone); or rate × duration."},
        {"injectors.*.mode", K::word, "-", "rate", {"rate", "allAtStart"}, R::any,
         "rate: one particle every 1/rate seconds from startTime; allAtStart: all at startTime."},
        {"injectors.*.rate", K::scalar, "1/s", "-", {}, R::positive,
         "Particles per second (mode rate); or count / duration."},
        {"injectors.*.duration", K::scalar, "s", "-", {}, R::positive,
         "How long it injects (mode rate), with count or rate."},
        {"injectors.*.startTime", K::scalar, "s", "0", {}, R::nonNegative,
         "When it starts; a file's row times are added to it."},
        {"injectors.*.density", K::scalar, "kg/m^3", "-", {}, R::positive,
         "Density ρp of this injector's particles; default particles.density. Every model "
         "takes each particle's own (README).",
         noMinimum, 1e5},
        {"injectors.*.material", K::dictionary, "-", "-", {}, R::any,
         "This injector's particles' material; a property not given is particles.material's."},
        {"injectors.*.material.bulkModulus", K::scalar, "Pa", "-", {}, R::positive,
         "Bulk modulus."},
        {"injectors.*.material.shearModulus", K::scalar, "Pa", "-", {}, R::positive,
         "Shear modulus."},
        {"injectors.*.material.yieldStress", K::scalar, "Pa", "-", {}, R::positive,
         "Yield stress."},
        {"injectors.*.material.surfaceEnergy", K::scalar, "J/m^2", "-", {}, R::positive,
         "Surface energy γ (Eq. 2.74)."},
        {"injectors.*.specificHeat", K::scalar, "J/(kg K)", "-", {}, R::positive,
         "Specific heat c_p of this injector's particles; default particles.specificHeat."},
        {"injectors.*.susceptibility", K::scalar, "-", "-", {}, R::any,
         "Magnetic susceptibility χm of this injector's particles, above −1; default "
         "physics.electromagnetic.magnetisation.susceptibility (needs its model linear)."},
        {"injectors.*.reinjectEscaped", K::boolean, "-", "no", {}, R::any,
         "Its escaped particles replaced by new ones of its own, as injection.reinjectEscaped "
         "(models disc, cone, patch)."},
        {"injectors.*.crossSpanSpeed", K::scalar, "m/s", "0", {}, R::nonNegative,
         "Random velocity across the axis (model disc), as injection.crossSpanSpeed."},
        {"injectors.*.coneCoeffs", K::dictionary, "-", "-", {}, R::any,
         "Model cone (OpenFOAM's coneInjection): solid (innerHalfAngle 0) or hollow."},
        {"injectors.*.coneCoeffs.innerHalfAngle", K::scalar, "deg", "0", {}, R::nonNegative,
         "Smallest angle of a direction to the axis.", noMinimum, 180},
        {"injectors.*.coneCoeffs.outerHalfAngle", K::scalar, "deg", "", {}, R::nonNegative,
         "Largest angle of a direction to the axis.", noMinimum, 180},
        {"injectors.*.coneCoeffs.speed", K::scalar, "m/s", "", {}, R::nonNegative,
         "Mean speed.", noMinimum, maximumGasSpeed},
        {"injectors.*.coneCoeffs.speedStandardDeviation", K::scalar, "m/s", "0", {},
         R::nonNegative, "Standard deviation of a normally distributed speed; 0: fixed."},
        {"injectors.*.patchCoeffs", K::dictionary, "-", "-", {}, R::any,
         "Model patch (OpenFOAM's patchInjection): points uniform in area over the faces of a "
         "patch of the mesh (carrier foamField); on a wedge, over the surface the patch sweeps "
         "about the axis."},
        {"injectors.*.patchCoeffs.patch", K::word, "-", "-", {}, R::any,
         "The patch, by its name in constant/polyMesh/boundary."},
        {"injectors.*.patchCoeffs.velocity", K::vector, "m/s", "-", {}, R::any,
         "Start velocity; not given: the gas velocity's part normal to the patch, (U·n) n."},
        {"injectors.*.file", K::word, "-", "-", {}, R::any,
         "Model file, its format told by its content (integrate/particle_file.h): a previous "
         "run's particles.h5 (its arrivals, or a frame: fileCoeffs.source); an OpenFOAM "
         "positions list (FoamFile header, as manualInjection's kinematicCloudPositions); else a "
         "CSV whose header names its columns (x y z u v w, d or r; optional t, wx wy wz, T, "
         "rho: a species per distinct density), a particle a row in order of t. Relative to the "
         "case directory."},
        {"injectors.*.fileCoeffs", K::dictionary, "-", "-", {}, R::any,
         "Model file: which particles of a particles.h5, the velocity of a positions list."},
        {"injectors.*.fileCoeffs.source", K::word, "-", "arrivals",
         namesOf(previousRunSourceNames()), R::any,
         "A particles.h5's arrivals (each at its arrival time), or the particles in flight in "
         "its frame at fileCoeffs.time, with their velocity, size, spin and temperature, all "
         "at startTime (integrate/previous_run.h)."},
        {"injectors.*.fileCoeffs.time", K::scalar, "s", "-", {}, R::nonNegative,
         "Source frame: the frame's time in the previous run, to 1e-6 of it."},
        {"injectors.*.fileCoeffs.velocity", K::vector, "m/s", "-", {}, R::any,
         "An OpenFOAM positions list: every particle's start velocity (OpenFOAM's U0); sizes "
         "from the injector's radiusDistribution."},
        {"injectors.*.ensembleCoeffs", K::dictionary, "-", "-", {}, R::any,
         "Model ensemble: count particles packed at rest in a box or a cylinder (Section 4.3; "
         "integrate/ensemble.h)."},
        {"injectors.*.ensembleCoeffs.method", K::word, "-", "randomSequentialAddition",
         namesOf(packingMethodNames()), R::any,
         "randomSequentialAddition (Widom, Fig. 4.1): up to saturation, φ ≈ 0.384 for equal "
         "spheres; lubachevskyStillinger (growth, Eq. 4.30–4.32, Algorithm 3): up to jamming, "
         "φ ≈ 0.63."},
        {"injectors.*.ensembleCoeffs.shape", K::word, "-", "box", namesOf(packingShapeNames()),
         R::any, "box: min to max; cylinder: the injector's centre (its base), axis and radius, "
                 "and length."},
        {"injectors.*.ensembleCoeffs.min", K::vector, "m", "-", {}, R::any,
         "Lower corner of the box."},
        {"injectors.*.ensembleCoeffs.max", K::vector, "m", "-", {}, R::any,
         "Upper corner of the box."},
        {"injectors.*.ensembleCoeffs.periodic", K::boolean, "-", "no", {}, R::any,
         "Box faces periodic (spheres may cross them, clear of the images: a bulk sample); no: "
         "walls, every sphere inside."},
        {"injectors.*.ensembleCoeffs.length", K::scalar, "m", "-", {}, R::positive,
         "Length of the cylinder along the axis."},
        {"injectors.*.ensembleCoeffs.growthRate", K::scalar, "-", "0.2", {}, R::positive,
         "lubachevskyStillinger: γ of dR_i/dt = γ R_i (Eq. 4.32), per unit time R̄/v̄; slower "
         "growth packs a little denser before jamming."},
        {"injectors.*.radiusDistribution", K::dictionary, "-", "-", {}, R::any,
         "Its own radius distribution (disc, cone, patch, ensemble, a file's positions list), "
         "with the keys of particles.radiusDistribution; default that one."},

        {"physics", K::dictionary, "-", "-", {}, R::any, "Forces on the particles."},
        {"physics.drag", K::word, "-", "haiderLevenspiel", namesOf(dragModelNames()), R::any,
         "Drag law (Eq. 3.17 for haiderLevenspiel; putnam is OpenFOAM's sphereDrag)."},
        {"physics.gravity", K::vector, "m/s^2", "(0 0 0)", {}, R::any,
         "Gravitational acceleration."},
        {"physics.buoyancy", K::boolean, "-", "on", {}, R::any,
         "Subtract the displaced gas's weight, (m − mf) g of Eq. 3.16."},
        {"physics.history", K::dictionary, "-", "-", {}, R::any,
         "History force (Eq. 3.3, 3.4, 3.8; physics/history_integrator.h, "
         "physics/finite_reynolds_history.h)."},
        {"physics.history.model", K::word, "-", "auto", namesOrAuto(historyModelNames()),
         R::any,
         "none: no history force; basset: Basset's kernel, window + exponential-sum tail; "
         "meiAdrian, kim: the finite-Reynolds kernels of Eq. 3.5 and 3.9 (Kim's with the "
         "initial-slip kernel K1 of Eq. 3.13 and G = 1 inside the integral: the acceleration "
         "factor of Eq. 3.10 is not modelled), a memory of the slip's increments (physics/"
         "finite_reynolds_history.h); auto: basset where "
         "the scene analysis finds it matters."},
        {"physics.history.accuracy", K::scalar, "-", "1e-3", {}, R::positive,
         "Relative error of the tail's kernel over the run; sets its window and terms.", 1e-10},
        {"physics.addedMass", K::switchOrAuto, "-", "auto", {}, R::any,
         "Added mass C_A = 1/2 (Eq. 3.3): inertia m_p + m_f/2, and C_A m_f DU/Dt."},
        {"physics.pressureGradient", K::switchOrAuto, "-", "auto", {}, R::any,
         "Undisturbed-flow force m_f DU/Dt (Eq. 3.3), DU/Dt = (U·∇)U of the steady carrier."},
        {"physics.lift", K::word, "-", "auto", namesOrAuto(liftModelNames()), R::any,
         "Saffman–Mei shear lift and/or Magnus spin lift (physics/lift.h); magnus needs spin; "
         "auto: each part where the scene analysis finds it matters."},
        {"physics.spin", K::switchOrAuto, "-", "auto", {}, R::any,
         "Particle spin under the viscous torque of Eq. 3.18, relaxing to half the vorticity; "
         "auto: on exactly when Magnus lift is."},
        {"physics.spinHistory", K::boolean, "-", "off", {}, R::any,
         "The spin's unsteady torque (Eq. 3.19, Feuillebois & Lasek): the history of the spin "
         "relative to the fluid, window + exponential tail to physics.history.accuracy; turns "
         "spin on."},
        {"physics.faxen", K::boolean, "-", "off", {}, R::any,
         "Faxén terms of Eq. 3.2 (Maxey & Riley 1983): drag and history on u + (R²/6)∇²u − v, "
         "added mass on u + (R²/10)∇²u − v; needs ∇²U, which planePoiseuille, taylorGreenVortex "
         "and oscillatingGas give (refused for foamField and the jets)."},
        {"physics.autoThreshold", K::scalar, "-", "0.01", {}, R::positive,
         "A term set to auto is turned off when the scene analysis estimates its effect below "
         "this: the velocity change it drives over the largest gas or particle speed, or the "
         "temperature change over fluid.temperature (README, scene analysis)."},
        {"physics.dispersion", K::dictionary, "-", "-", {}, R::any,
         "Turbulent dispersion (Section 3.9, physics/dispersion.h); needs k, ε from the carrier."},
        {"physics.dispersion.model", K::word, "-", "auto", namesOrAuto(dispersionModelNames()),
         R::any,
         "eddyInteraction: Gosman–Ioannides eddies with exponential lifetimes; langevin: "
         "continuous random walk; auto: eddyInteraction where the scene analysis finds it "
         "matters."},
        {"physics.dispersion.Cmu", K::scalar, "-", "0.09", {}, R::positive,
         "k-ε C_μ: eddy length C_μ^(3/4) k^(3/2)/ε and, with Sc_t, the time scale T_L."},
        {"physics.dispersion.turbulentSchmidtNumber", K::scalar, "-", "0.7", {}, R::positive,
         "Sc_t: T_L = 3 C_μ k/(2 Sc_t ε), so the tracer diffusivity (2k/3) T_L is ν_t/Sc_t."},
        {"physics.heatTransfer", K::dictionary, "-", "-", {}, R::any,
         "Convective heating of the particles (Section 3.8, physics/heat_transfer.h)."},
        {"physics.heatTransfer.model", K::word, "-", "auto",
         namesOrAuto(heatTransferModelNames()), R::any,
         "Nusselt correlation: ranzMarshall (Eq. 3.27) or acrivosTaylor (Eq. 3.28); "
         "michaelidesFeng: the unsteady Eq. 3.29 (Nu = 2 conduction, the fluid's heat capacity "
         "and the history of the temperature difference, to physics.history.accuracy); auto: "
         "ranzMarshall where the scene analysis finds it matters."},
        {"physics.electromagnetic", K::dictionary, "-", "-", {}, R::any,
         "Forces on charged particles in applied fields (Section 2.7, physics/electromagnetic.h)."},
        {"physics.electromagnetic.model", K::word, "-", "none",
         namesOf(electromagneticModelNames()), R::any,
         "lorentz: q (E + v × B) of Eq. 2.93, with the drag by the exact Lorentz–drag flow "
         "(integrate/lorentz_flow.h; with coils its midpoint rule); not with the unsteady "
         "forces."},
        {"physics.electromagnetic.E", K::vector, "V/m", "(0 0 0)", {}, R::any,
         "Uniform electric field E of Eq. 2.93."},
        {"physics.electromagnetic.B", K::vector, "T", "(0 0 0)", {}, R::any,
         "Uniform magnetic field B of Eq. 2.93; the coils' fields add to it."},
        {"physics.electromagnetic.coils", K::dictionary, "-", "-", {}, R::any,
         "Circular current loops whose fields join B (physics/current_loop.h: Jackson's "
         "elliptic-integral form, anywhere off the wire); not with adaptiveRungeKutta."},
        {"physics.electromagnetic.coils.*", K::dictionary, "-", "-", {}, R::any,
         "One coil, named by its key."},
        {"physics.electromagnetic.coils.*.centre", K::vector, "m", "(0 0 0)", {}, R::any,
         "Centre of the loop."},
        {"physics.electromagnetic.coils.*.axis", K::vector, "-", "(0 0 1)", {}, R::any,
         "Normal of the loop's plane; the current circulates anticlockwise about it."},
        {"physics.electromagnetic.coils.*.radius", K::scalar, "m", "-", {}, R::positive,
         "Radius a of the loop."},
        {"physics.electromagnetic.coils.*.current", K::scalar, "A", "-", {}, R::any,
         "Current I of the loop (the ampere-turns of a thin coil of many turns)."},
        {"physics.electromagnetic.magnetisation", K::dictionary, "-", "-", {}, R::any,
         "Magnetisable particles (Section 2.7.2, physics/magnetic_force.h)."},
        {"physics.electromagnetic.magnetisation.model", K::word, "-", "none",
         namesOf(magnetisationModelNames()), R::any,
         "linear: M = χm H (Eq. 2.107), the force χm V/(µ0 µr) (∇B)ᵀ B of Eq. 2.110 on every "
         "particle, charged or not; needs coils (a uniform B pulls nothing)."},
        {"physics.electromagnetic.magnetisation.susceptibility", K::scalar, "-", "0", {},
         R::any,
         "Volume magnetic susceptibility χm of the particles' material, above −1: > 0 "
         "paramagnetic (drawn into strong fields), < 0 diamagnetic."},
        {"physics.electromagnetic.charge", K::dictionary, "-", "-", {}, R::any,
         "Charge of each particle, a lumped charge at its centre (Section 2.7.1)."},
        {"physics.electromagnetic.charge.model", K::word, "-", "fixed",
         namesOf(chargeModelNames()), R::any,
         "fixed: q = value [C] for every particle; surface: q = value·4πR² (value a surface "
         "charge density [C/m²])."},
        {"physics.electromagnetic.charge.value", K::scalar, "C or C/m^2", "0", {}, R::any,
         "The charge (fixed) or surface charge density (surface)."},
        {"physics.electromagnetic.charge.oppositeSignFraction", K::scalar, "-", "0", {},
         R::nonNegative,
         "The expected fraction of particles charged −value instead of value, in [0, 1] "
         "(bipolar charging); each particle's sign is drawn from injection.seed and its id."},
        {"physics.electromagnetic.coulomb", K::dictionary, "-", "-", {}, R::any,
         "Coulomb forces between the charged particles (Eq. 2.94, physics/coulomb.h); not "
         "chosen by the scene analysis."},
        {"physics.electromagnetic.coulomb.model", K::word, "-", "none",
         namesOf(coulombModelNames()), R::any,
         "shifted: Coulomb's law between every pair closer than the cutoff, truncated by the "
         "shift (1 − r²/r_c²)² of Eq. 2.97 (potential and force continuous, zero at the cutoff), "
         "applied as velocity-Verlet half kicks around the stream step (second order); needs "
         "model lorentz (E and B may be zero)."},
        {"physics.electromagnetic.coulomb.cutoff", K::scalar, "m", "1e-3", {}, R::positive,
         "Truncation distance r_c of Eq. 2.97, also the cell edge of the pair search.", 1e-9},
        {"physics.electromagnetic.coulomb.permittivity", K::scalar, "-", "1", {}, R::positive,
         "Relative permittivity ε_r of the gas: k = 1/(4π ε0 ε_r).", 1},

        {"time", K::dictionary, "-", "", {}, R::any, "Time control."},
        {"time.dt", K::scalar, "s", "-", {}, R::positive,
         "Time step; default: the scene analysis's choice from the particles' paths (flow "
         "scale, cell crossing, response time, eddy lifetime, collision time, Coulomb time). At "
         "most 1e9 steps to time.endTime (run/run_limits.h)."},
        {"time.endTime", K::scalar, "s", "", {}, R::positive, "Latest end of the run."},
        {"time.stopWhenAllDone", K::boolean, "-", "yes", {}, R::any,
         "Stop before endTime once every particle is injected and has arrived or escaped."},
        {"time.integrator", K::word, "-", "exponentialMidpoint", namesOf(integratorNames()),
         R::any, "Time integrator (integrate/integrator.h)."},
        {"time.tolerance", K::scalar, "-", "1e-6", {}, R::positive,
         "adaptiveRungeKutta only (an error with another integrator): TOL of the step control "
         "(Eq. 4.29), below 1; each sub-step's error estimate relative to the particle's radius "
         "(position) and speed (velocity)."},

        {"collisions", K::dictionary, "-", "-", {}, R::any,
         "Contacts between particles, and the laws of every impulse contact (collide/)."},
        {"collisions.model", K::word, "-", "auto", namesOrAuto(collisionModelNames()), R::any,
         "Particle–particle collisions: none, impulse (collide-and-stream, Eq. 2.34–2.58), "
         "softSphere (Hertz–Mindlin forces, Eq. 2.4–2.14; rebound surfaces become soft walls), "
         "or auto: impulse where the scene analysis expects collisions."},
        {"collisions.restitution", K::dictionary, "-", "-", {}, R::any,
         "Restitution of impulse contacts (physics/restitution.h)."},
        {"collisions.restitution.model", K::word, "-", "velocityDependent",
         namesOf(restitutionModelNames()), R::any,
         "constant: e = coefficient; velocityDependent: elastic below v_Y (Eq. 2.63), Eq. 2.62 "
         "above, from the materials' moduli and yield stress."},
        {"collisions.restitution.coefficient", K::scalar, "-", "0.9", {}, R::nonNegative,
         "e of the constant model."},
        {"collisions.restitution.yieldPressureFactor", K::scalar, "-", "3", {}, R::positive,
         "α of the mean contact pressure αY (Eq. 2.60–2.64): 3 for metals, about 1 for foams."},
        {"collisions.friction", K::dictionary, "-", "-", {}, R::any,
         "Coulomb stick–slip friction of impulse contacts (Eq. 2.30–2.31)."},
        {"collisions.friction.static", K::scalar, "-", "0.3", {}, R::nonNegative,
         "μ_s: the contact sticks while the stick impulse is below μ_s times the normal one."},
        {"collisions.friction.dynamic", K::scalar, "-", "0.3", {}, R::nonNegative,
         "μ_d: tangential impulse of a slipping contact per normal impulse; the Coulomb limit "
         "μ of softSphere contacts."},
        {"collisions.friction.regularisation", K::word, "-", "none",
         namesOf(frictionRegularisationNames()), R::any,
         "softSphere tangential law: none, the Mindlin spring with the Coulomb limit (Eq. 2.5, "
         "2.14); or regularised Coulomb friction μ R(v_slip) F_n (Eq. 2.65): linear (2.66), tanh "
         "(2.67), algebraic (2.68). A sphere sliding on a plane rolls from v = 5/7 v0 on."},
        {"collisions.friction.slipSpeed", K::scalar, "m/s", "1e-3", {}, R::positive,
         "ε of the regularised friction (Eq. 2.66–2.68): slip speed over which it builds up."},
        {"collisions.heating", K::boolean, "-", "on", {}, R::any,
         "Contacts (impulse pairs, rebounds, sticking; soft-sphere damping and sliding) heat "
         "their particles by the energy they dissipate (Eq. 2.117), shared by heat capacity; "
         "with physics.heatTransfer on."},
        {"collisions.conduction", K::word, "-", "none", namesOf(contactConductionNames()),
         R::any,
         "Heat conducted between touching softSphere particles, with physics.heatTransfer on: "
         "none, or batchelorOBrien: Q = π K_f a ΔT ln(K_p/K_f)², a = 2R* (Eq. 2.118), from "
         "particles.thermalConductivity and fluid.thermalConductivity."},
        {"collisions.softSphereCoeffs", K::dictionary, "-", "-", {}, R::any,
         "The softSphere model (collide/soft_sphere_collisions.h); its damping follows from "
         "restitution.coefficient, which must then be constant."},
        {"collisions.softSphereCoeffs.damping", K::word, "-", "restitution",
         namesOf(softSphereDampingNames()), R::any,
         "restitution: Hertz impacts restitute e to second order in the step (at t_c/20 within "
         "0.27 % for e = 0.2, 0.14 % for 0.5, 0.08 % for 0.8); tsuji: LIGGGHTS' "
         "β = ln e/√(ln²e + π²)."},
        {"collisions.softSphereCoeffs.neighbourSkin", K::scalar, "-", "0.2", {}, R::nonNegative,
         "Verlet-list skin per largest particle radius: the list is rebuilt when a particle has "
         "moved half of it (0: every step)."},
        {"collisions.softSphereCoeffs.contactLaw", K::word, "-", "hertz",
         namesOf(normalContactLawNames()), R::any,
         "Normal force law (physics/contact_laws.h): hertz (Eq. 2.4, damped as Eq. 2.6–2.8); "
         "linearSpringDashpot (Eq. 2.6–2.7: e = exp(−πζ/√(1−ζ²)), t_c = π/ω_d; second order in "
         "the step, at t_c/20 within 1.2 % for e = 0.2, 0.25 % for 0.5, 0.05 % for 0.8); "
         "viscoelasticHertz (Brilliantov, Eq. 2.8: e falls with impact speed); waltonBraun "
         "(Eq. 2.9–2.10: k_U = k_L/e², e = √(k_L/k_U)). Verified on Chung & Ooi tests 1–3."},
        {"collisions.softSphereCoeffs.normalStiffness", K::scalar, "N/m", "-", {}, R::positive,
         "k of linearSpringDashpot, loading k_L of waltonBraun (Eq. 2.6, 2.9)."},
        {"collisions.softSphereCoeffs.dissipativeTime", K::scalar, "s", "-", {}, R::nonNegative,
         "Brilliantov's A of viscoelasticHertz: F = K_n(δ^{3/2} + 3/2 A √δ dδ/dt) (Eq. 2.8)."},

        {"deposition", K::dictionary, "-", "-", {}, R::any,
         "Adhesion on surfaces whose interaction is deposit, and on their deposit (Eq. 5.7–5.9)."},
        {"deposition.adhesion", K::word, "-", "interfaceEnergy", namesOf(adhesionModelNames()),
         R::any,
         "interfaceEnergy: F = 2πR*·2√(γ1γ2) (Eq. 2.72–2.74, 5.7); hamaker: F = A R*/(6ε0²) "
         "(Eq. 2.75); jkr: the JKR pull-off 3/2 πWR* (Eq. 2.84); dmt: 2πWR* (Eq. 2.91); "
         "taborMap: JKR's where Tabor's μ_T (Eq. 2.92, ε0 = contactSeparation) ≥ 1, else DMT's."},
        {"deposition.adhesionFactor", K::scalar, "-", "1", {}, R::positive,
         "α multiplying the adhesion force (Table 5.2 assumes 5000)."},
        {"deposition.hamakerConstant", K::scalar, "J", "-", {}, R::positive,
         "Hamaker constant A (adhesion hamaker)."},
        {"deposition.contactSeparation", K::scalar, "m", "4e-10", {}, R::positive,
         "Separation ε0 of surfaces in contact (adhesion hamaker, taborMap)."},

        {"surfaces", K::dictionary, "-", "", {}, R::any,
         "Named surfaces that particles meet."},
        {"surfaces.*", K::dictionary, "-", "-", {}, R::any, "One surface, named by its key."},
        {"surfaces.*.type", K::word, "-", "plane", {"plane", "patch"}, R::any,
         "Surface shape: plane (point and normal), or patch, a wall patch of the foamField "
         "carrier's 3-D mesh (spheres meet its faces, not their convex edges)."},
        {"surfaces.*.point", K::vector, "m", "-", {}, R::any, "A point on the plane (type plane)."},
        {"surfaces.*.normal", K::vector, "-", "-", {}, R::any,
         "Plane normal pointing into the gas, normalised on reading (type plane)."},
        {"surfaces.*.patch", K::word, "-", "-", {}, R::any,
         "Name of the mesh patch, of type wall or patch in constant/polyMesh/boundary (type "
         "patch)."},
        {"surfaces.*.interaction", K::word, "-", "absorb", namesOf(surfaceInteractionNames()),
         R::any,
         "absorb: record the arrival and remove the particle; rebound: impulse law (Eq. "
         "2.15–2.33); deposit: stick where Eq. 5.9 holds, else rebound; erode: rebound, loading "
         "the porous layer of `erosion` (Section 5.2)."},
        {"surfaces.*.material", K::dictionary, "-", "-", {}, R::any,
         "Surface properties (Table 5.2), for rebound and deposition."},
        {"surfaces.*.material.bulkModulus", K::scalar, "Pa", "-", {}, R::positive,
         "Bulk modulus."},
        {"surfaces.*.material.shearModulus", K::scalar, "Pa", "-", {}, R::positive,
         "Shear modulus."},
        {"surfaces.*.material.yieldStress", K::scalar, "Pa", "-", {}, R::positive,
         "Yield stress."},
        {"surfaces.*.material.surfaceEnergy", K::scalar, "J/m^2", "-", {}, R::positive,
         "Surface energy γ."},
        {"surfaces.*.erosion", K::dictionary, "-", "-", {}, R::any,
         "The porous layer of an erode surface (Fig. 5.1): the plane's material is its matrix."},
        {"surfaces.*.erosion.thickness", K::scalar, "m", "-", {}, R::positive,
         "Layer thickness d (Fig. 5.1)."},
        {"surfaces.*.erosion.width", K::scalar, "m", "-", {}, R::positive,
         "Layer width w, a square centred on the plane's point (Fig. 5.1)."},
        {"surfaces.*.erosion.porosity", K::scalar, "-", "0", {}, R::nonNegative,
         "Pore volume fraction p (Eq. 5.1–5.3, v2 = 1 − p); the pores are a phase C = 1e-4 as "
         "stiff.", noMinimum, 0.95},
        {"surfaces.*.erosion.boundWeight", K::scalar, "-", "0.5", {}, R::nonNegative,
         "φ of Eq. 5.3: the moduli φ·upper + (1 − φ)·lower Hashin–Shtrikman bound.", noMinimum,
         1},
        {"surfaces.*.erosion.threshold", K::scalar, "Pa", "-", {}, R::positive,
         "Damage threshold σ0 of the matrix (Eq. 5.5–5.6)."},
        {"surfaces.*.erosion.cells", K::integerTriple, "-", "(32 32 8)", {}, R::atLeastOne,
         "Grid cells across the width (two directions, even) and the thickness."},

        {"domain", K::dictionary, "-", "-", {}, R::any,
         "Particles leaving this box escape; required for an analytic carrier, the mesh's box "
         "by default for foamField."},
        {"domain.min", K::vector, "m", "", {}, R::any, "Lower corner."},
        {"domain.max", K::vector, "m", "", {}, R::any, "Upper corner."},

        {"output", K::dictionary, "-", "", {}, R::any, "What is written to CASE/slides/."},
        {"output.interval", K::scalar, "s", "", {}, R::positive,
         "Time between particle frames (particles_NNNNNN.vtp). At most 1e6 frames to "
         "time.endTime (run/run_limits.h)."},
        {"output.carrierResolution", K::integerTriple, "-", "(96 48 48)", {}, R::atLeastOne,
         "Lattice points per axis of carrier.vti over the domain; the grid must fit in the "
         "machine's memory (run/run_limits.h)."},
        {"output.fields", K::wordList, "-",
         "(id diameter velocity speed state temperature angularVelocity)",
         namesOf(particleFieldNames()), R::any,
         "Point arrays of each particle frame; temperature only with physics.heatTransfer, "
         "angularVelocity [rad/s] only where the particles spin (physics.spin, collisions, or a "
         "surface that rebounds or deposits)."},
        {"output.hdf5", K::boolean, "-", "yes", {}, R::any,
         "Also write every frame and the arrivals to particles.h5, indexed by particles.xmf."},
    };
    // clang-format on
    // Each injector's radiusDistribution takes the keys of particles.radiusDistribution.
    const std::string particleSizes = "particles.radiusDistribution.";
    std::vector<KeyDeclaration> injectorSizes;
    for (const KeyDeclaration& key : keys)
        if (key.path.starts_with(particleSizes)) {
            KeyDeclaration copy = key;
            copy.path = "injectors.*.radiusDistribution." + key.path.substr(particleSizes.size());
            injectorSizes.push_back(copy);
        }
    const auto after = std::find_if(keys.begin(), keys.end(), [](const KeyDeclaration& key) {
        return key.path == "injectors.*.radiusDistribution";
    });
    keys.insert(after + 1, injectorSizes.begin(), injectorSizes.end());
    return keys;
}

} // namespace

bool keyPathMatches(std::string_view pattern, std::string_view path) {
    while (true) {
        const auto patternDot = pattern.find('.');
        const auto pathDot = path.find('.');
        const auto patternHead = pattern.substr(0, patternDot);
        const auto pathHead = path.substr(0, pathDot);
        if (patternHead != "*" && patternHead != pathHead) return false;
        if (patternDot == std::string_view::npos || pathDot == std::string_view::npos)
            return patternDot == pathDot;
        pattern.remove_prefix(patternDot + 1);
        path.remove_prefix(pathDot + 1);
    }
}

namespace {

std::string kindName(const KeyDeclaration& key) {
    switch (key.kind) {
    case KeyKind::dictionary: return "dictionary";
    case KeyKind::scalar: return "scalar";
    case KeyKind::integer: return "integer";
    case KeyKind::word: return "word";
    case KeyKind::wordList: return "list of words";
    case KeyKind::boolean: return "switch";
    case KeyKind::switchOrAuto: return "switch \\| auto";
    case KeyKind::vector: return "vector";
    case KeyKind::integerTriple: return "3 integers";
    case KeyKind::timeRange: return "all \\| (start end)";
    }
    return "";
}

} // namespace

const std::vector<KeyDeclaration>& sceneKeys() {
    static const std::vector<KeyDeclaration> keys = declareKeys();
    return keys;
}

const KeyDeclaration* findSceneKey(std::string_view path) {
    for (const auto& key : sceneKeys())
        if (keyPathMatches(key.path, path)) return &key;
    return nullptr;
}

namespace {

/// The declared bounds as a sentence of the doc column, e.g. " At most 1e+05."
std::string rangeText(const KeyDeclaration& key) {
    std::ostringstream text;
    if (std::isfinite(key.minimum)) text << " At least " << key.minimum << ".";
    if (std::isfinite(key.maximum)) text << " At most " << key.maximum << ".";
    return text.str();
}

} // namespace

std::string sceneKeysMarkdown() {
    std::ostringstream table;
    table << "| key | type | unit | default | description |\n|---|---|---|---|---|\n";
    for (const auto& key : sceneKeys()) {
        std::string type = kindName(key);
        if (!key.allowed.empty()) {
            type.clear();
            for (const auto& name : key.allowed) type += (type.empty() ? "" : " \\| ") + name;
            if (key.kind == KeyKind::wordList) type = "list of: " + type;
        }
        const std::string fallback = key.required()   ? "required"
                                     : key.optional() ? "—"
                                                      : "`" + key.fallback + "`";
        table << "| `" << key.path << "` | " << type << " | " << key.unit << " | " << fallback
              << " | " << key.doc << rangeText(key) << " |\n";
    }
    return table.str();
}

} // namespace slides
