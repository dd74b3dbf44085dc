// Maxey–Riley step: drag, added mass, pressure gradient, Basset history, lift and spin, and the
// Faxén terms of Eq. 3.2 (physics/faxen.h), when any of these is on; the stepper keeps its
// exponential schemes otherwise.
//
// Reference: Eq. 3.3/3.4 and 3.18 of the reference. Per step of length h, for every particle:
//   1. the carrier at x_n (U, ∇U when a term needs it, and ∂U/∂t of an unsteady carrier for the
//      fluid acceleration DU/Dt = ∂U/∂t + (U·∇)U), and at the predicted end x*, both
//      sampled by the stepper (from the particles' mesh cells, with their eddy fluctuations
//      when dispersion is on, so the gas velocity a particle sees is U + ū'; k, ε and T of the
//      start sample serve dispersion and heating),
//      extrapolated on the smooth part w = v + s0 φ of the velocity (the start mode of
//      physics/history_integrator.h carries the √t of a release with slip):
//      w* = 2 w_n − w_{n−1}, x* = x_n + h (w_n + w*)/2 − s0 ∫φ (third-order accurate, so the
//      history term's √h sensitivity to u_{n+1} costs no order), v* = w* − s0 φ_{n+1};
//   2. v_{n+1} from the trapezoid rule with the history term implicit in v_{n+1}
//      (physics/history_integrator.h), τ of the nonlinear drag frozen at the predicted midpoint
//      slip, added mass in the effective mass (physics/unsteady.h), fluid acceleration, gravity
//      and lift (physics/lift.h) by the trapezoid rule; spin relaxed exactly (physics/spin.h),
//      or, with its history (Eq. 3.19), by the same implicit history step on σ = ½∇×U − ω.
// Order 2; the trapezoid rule keeps the stiff drag stable for any h/τ (A-stable, though not
// L-stable: for h ≫ τ the slip decays in alternating steps). The history weights take a
// particle's shorter first step (released inside a step) at its length; they assume dt for all
// later steps, so the run's shortened last step makes an O(h²) error there. Per-particle state
// lives in ParticleCloud::modelState: age, w_{n−1}, then the history start s0, I_n and the window +
// tail memory (A_n and the memory of physics/finite_reynolds_history.h for Mei & Adrian's or
// Kim's kernel), and the same three for the spin's history, each only when its term is on.
//
// Particles of differing densities (species, integrate/injection_settings.h) take their own ρp in
// every term; each particle's step is the same bits as in a run of its species alone.
//
//     physics { history { model basset; accuracy 1e-3; } addedMass on; pressureGradient on;  // or
//               meiAdrian, kim
//               lift saffmanMei; spin on; spinHistory on; faxen on; }
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/carrier/carrier_settings.h"
#include "slides/core/particle_cloud.h"
#include "slides/integrate/time_settings.h"
#include "slides/physics/drag.h"
#include "slides/physics/finite_reynolds_history.h"
#include "slides/physics/history_integrator.h"
#include "slides/physics/physics_settings.h"
#include "slides/physics/unsteady.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace slides {

class MaxeyRileyStepper {
public:
    /// Used when PhysicsSettings::unsteadyForces(); otherwise the stepper's schemes run.
    /// densities[s] is ρp of species s (one entry when the particles are alike). The history
    /// memory is sized for steps of time.dt up to time.endTime. With an unsteady carrier
    /// (steadyCarrier false) the fluid acceleration takes ∂U/∂t from the samples too.
    MaxeyRileyStepper(const PhysicsSettings& physics, const FluidSettings& fluid,
                      std::span<const double> densities, const TimeSettings& time,
                      bool steadyCarrier = true);

    /// Doubles of model state per particle: the first of each particle's ParticleCloud::stateWidth.
    std::size_t stateWidth() const { return width_; }
    /// What the step needs of both carrier samples.
    CarrierNeeds needs() const { return needs_; }

    /// Fills out with the gas the particles see at the given points at the step's end.
    using EndSampler = std::function<void(const std::vector<Vec3>& points, CarrierSample& out)>;

    /// Advances every particle i over stepLengths[i]: gasStart is the gas each sees at the
    /// step's start (with what needs() asks for), sampleEnd samples the predicted ends.
    /// species[i] is particle i's species and densities[i] its ρp (both empty: all of species 0).
    void advance(ParticleCloud& cloud, const CarrierSample& gasStart, const EndSampler& sampleEnd,
                 const std::vector<double>& stepLengths, std::span<const std::int32_t> species,
                 std::span<const double> densities);

private:
    /// What ρp sets in the step's terms, for one species.
    struct SpeciesTerms {
        double density;                 ///< ρp [kg/m³]
        DragParameters drag;            ///< with ρp
        double effectiveDensity;        ///< ρp + C_A ρf (physics/unsteady.h)
        Vec3 bodyAcceleration;          ///< gravity and buoyancy per effective mass
        double fluidAccelerationFactor; ///< of DU/Dt: pressure gradient and added mass
    };

    /// The gas velocity the drag and history see at sample i: u, or u + (R²/6)∇²u with the
    /// Faxén terms (physics/faxen.h).
    Vec3 dragGasVelocity(const CarrierSample& gas, std::size_t i, double radius) const;
    /// ω after a step of h under the steady and history torques of Eq. 3.19, with the fluid
    /// rotation ½∇×U at its start and end; state holds σ0, I_n and the memory.
    Vec3 spinWithHistory(double* state, double age, const Vec3& spin, const Vec3& rotationStart,
                         const Vec3& rotationEnd, double radius, double density, double h) const;

    PhysicsSettings physics_;
    FluidSettings fluid_;
    FluidInertia inertia_;
    std::vector<SpeciesTerms> species_; ///< one entry a species
    CarrierNeeds needs_;
    std::optional<WindowTailLayout> memory_;             ///< of both histories, when either is on
    std::optional<FiniteReynoldsLayout> finiteReynolds_; ///< Mei & Adrian's or Kim's kernel
    const FiniteReynoldsKernel* finiteReynoldsTables_ = nullptr;
    bool history_ = false, spinHistory_ = false;
    std::size_t historyOffset_ = 0, spinHistoryOffset_ = 0, width_ = 0;

    CarrierSample gasEnd_;
    std::vector<Vec3> predicted_;           ///< x* of each particle
    std::vector<Vec3> predictedVelocity_;   ///< v* at the step's end
    std::vector<Vec3> smoothVelocity_;      ///< w_n = v_n + s0 φ(age)
    std::vector<StartModeStep> startModes_; ///< φ and its integrals at both ends of the step
    std::vector<double> slipSpeeds_;        ///< |u − v| the drag is taken at: N starts, N ends
    std::vector<double> responseTimes_;     ///< τ at those slips, the same layout
};

} // namespace slides
