// Scene analysis: what a scene's physics needs, from its inputs and pilot paths through its
// carrier, and the time step it should take.
//
// analyseScene traces pilot particles with drag, gravity and buoyancy only
// (analysis/pilot_paths.h) and estimates along their paths the effect each other term would
// have (analysis/term_estimates.h), in one measure per kind of term:
//   forces (history, added mass, pressure gradient, Saffman–Mei and Magnus lift): the largest
//     velocity deviation the term drives against drag, over the reference speed U_ref (the
//     largest gas or particle speed on the paths); Basset's acceleration is product-integrated
//     over each path's slip, the others are the models' own accelerations;
//   dispersion: the largest rms turbulent velocity a particle takes on (Tchen) over U_ref;
//   heat transfer: the largest temperature change over fluid.temperature (with an unknown c_p,
//     the largest gas-to-particle temperature difference, its upper bound);
//   collisions: the expected collisions per particle over its flight (kinetic rate in the
//     spray's number density) times the relative speed of neighbours, over U_ref: each
//     collision changes a velocity by about that speed.
// A term left to `auto` is turned on where its effect reaches physics.autoThreshold (and it
// has the inputs it needs), so that a term auto drops changes the result by less than the
// threshold in its measure (tests/verification/test_scene_analysis.cpp checks this on two
// contrasting scenes). Spin follows Magnus lift.
//
// Without time.dt the step is the smallest of: the flow limit (for a tracer, the gas velocity
// it sees, changing at ∂U/∂t + (∇U)v, changes by at most flowChangePerStep U_ref a step: an
// unsteady carrier's period is resolved), the cell crossing limit (for a
// tracer, half a cell of the carrier's resolution length a step) — both relaxed by √(τ/t)
// at a point reached after a flight t shorter than the response time τ, since the error
// the step makes in the gas a particle sees has moved its velocity by (t/τ) h² there —, a
// fifth of the response time (explicitEuler or
// an unsteady force on), the Lagrangian eddy time (dispersion; the eddy model is verified up
// to dt = 2 T_L), a quarter of the mean time between collisions (collisions), a
// stepsPerSoftContact-th of the shortest Hertz contact (softSphere: the smallest spheres at
// U_ref, Eq. 2.59), a stepsPerCoulombTime-th of the Coulomb time scale of two touching
// particles (physics/coulomb.h: the smallest and the largest), a stepsPerCoilRadius-th of the
// time to cross the smallest coil's radius (coils: at the reference speed, or the speed of a
// magnetisable particle falling into the coils' field), the output interval; each at the 1st
// percentile of the path points, so that one point does not set it. A scene without gas (carrier
// none) is not traced: its auto terms stay off and its time step is the one given.
//
//     physics { autoThreshold 0.01; }   // time { dt ...; } given: the analysis only reports
#pragma once

#include "slides/analysis/physics_terms.h"
#include "slides/analysis/pilot_paths.h"
#include "slides/carrier/carrier_field.h"
#include "slides/config/scene.h"

#include <string>
#include <vector>

namespace slides {

/// The gas velocity change a particle may see in one step of the default time step, over U_ref.
inline constexpr double flowChangePerStep = 0.02;
/// Steps over the shortest soft-sphere contact (softSphere collisions; Eq. 2.59).
inline constexpr double stepsPerSoftContact = 20;
/// Steps over the Coulomb time scale √(m s³/(k q²)) of two touching particles (Coulomb forces;
/// velocity Verlet's energy error there is then about 0.6 % a close pair).
inline constexpr double stepsPerCoulombTime = 10;
/// Steps over the time to cross the smallest coil's radius (physics.electromagnetic.coils; the
/// field's midpoint rule is second order in the step over that time).
inline constexpr double stepsPerCoilRadius = 20;

/// One row of the decision table.
struct TermDecision {
    PhysicsTerm term;
    double effect = 0;      ///< estimated effect, in the term's measure
    double peakToDrag = 0;  ///< largest force over drag on the paths (NaN: not a force)
    std::string measure;    ///< what effect measures
    bool automatic = false; ///< left to auto
    bool on = false;        ///< the decision (or the setting)
    std::string reason;     ///< why
};

/// A time-step limit: its name and value [s].
struct TimeStepLimit {
    std::string name;
    double value;
};

/// Figures of the scene, for the decision table and summary.json.
struct SceneFigures {
    double referenceSpeed = 0;  ///< U_ref [m/s]
    double densityRatio = 0;    ///< ρp/ρf
    double stokesNumberMin = 0; ///< τ_St/(R_nozzle/U_ref) of the smallest pilot particle
    double stokesNumberMax = 0; ///< ... of the largest
    double reynoldsMin = 0;     ///< particle Reynolds number on the paths
    double reynoldsMax = 0;
    double responseTimeMin = 0; ///< drag response time on the paths [s]
    double responseTimeMax = 0;
    double flightTime = 0;            ///< median time to the end of a path [s]
    double volumeFractionNozzle = 0;  ///< particle volume fraction at the nozzle
    double volumeFractionMax = 0;     ///< ... largest along the spray
    double collisionsPerParticle = 0; ///< expected over the flight
    double biotMax = 0;               ///< h (R/3)/K_p; NaN without particles.thermalConductivity
};

struct SceneAnalysis {
    SceneFigures figures;
    PilotSummary pilot;
    double threshold = 0;
    std::vector<TermDecision> terms;
    double suggestedTimeStep = 0;  ///< the analysis's time step [s]
    std::string timeStepLimitedBy; ///< the limit that set it
    std::vector<TimeStepLimit> timeStepLimits;
    bool timeStepGiven = false; ///< time.dt (or --dt) was given: it is kept
    std::vector<std::string> warnings;
};

/// Analyses the scene on its carrier (the pilot runs with time.dt if given, else with a
/// provisional step from the nozzle).
SceneAnalysis analyseScene(const Scene& scene, const CarrierField& carrier);

/// Applies the analysis: turns on the auto terms it decided on, sets time.dt if not given.
void applyAnalysis(const SceneAnalysis& analysis, Scene& scene);

/// The decision table and figures as printed at the start of a run.
std::string describeAnalysis(const SceneAnalysis& analysis);

} // namespace slides
