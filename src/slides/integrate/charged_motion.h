// ChargedMotion: the step loop's use of the Lorentz force (physics/electromagnetic.h) — each
// particle's charge, set as it enters, and its step by the exact Lorentz–drag flow
// (integrate/lorentz_flow.h) in place of the drag schemes; under adaptiveRungeKutta, the Lorentz
// force in its sub-steps instead (integrate/adaptive_runge_kutta_batch.h).
//
// Reference: Eq. 2.93 with the drag of Eq. 3.16. With gas, the exponential midpoint rule of the
// drag schemes: a half step of the flow with the gas and τ of the step's start predicts the
// midpoint, where the gas is sampled; the whole step then takes the flow from the start with the
// midpoint's gas and τ (from the slip at the predicted midpoint). Second order for a gas that
// varies along the path; exact in uniform gas under Stokes drag and without gas (the Larmor
// gyration, the E × B drift). With no gas the flow has no drag (λ = 0). Where species differ,
// each particle's own ρp sets its mass m = 4/3 π R³ ρp (so q/m) and its τ, and its own body
// acceleration joins qE/m.
//
// With coils the fields vary in space: E, B and the magnetisable particles' force
// χm/(µ0 µr ρp) (∇B)ᵀ B (Eq. 2.110) are taken at the step's start for the half step and at the
// predicted midpoint for the whole step, with gas and without (then the explicit midpoint rule
// of the flow: second order, no longer exact).
//
//     physics { electromagnetic { model lorentz; E (0 0 1e5); B (0 0 0.5);
//                                 charge { model fixed; value 1e-12; } } }
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/core/particle_cloud.h"
#include "slides/integrate/species_values.h"
#include "slides/physics/drag.h"
#include "slides/physics/electromagnetic.h"

#include <functional>
#include <vector>

namespace slides {

class ChargedMotion {
public:
    /// susceptibility: the particles' χm where they are alike (ParticleSettings).
    ChargedMotion(const ElectromagneticSettings& fields, const DragParameters& drag,
                  const Vec3& bodyAcceleration, double susceptibility);

    /// Charges the particles from index first on (those that just entered).
    void charge(ParticleCloud& cloud, std::size_t first) const;

    /// Samples the gas at the given points (the predicted midpoints) into out.
    using MidpointSampler =
        std::function<void(const std::vector<Vec3>& points, CarrierSample& out)>;

    /// Advances every particle i over stepLengths[i] through gas whose velocity at the step's
    /// start is gasStart.velocity[i]; species: the particles' own ρp and a, if they differ.
    void advance(ParticleCloud& cloud, const CarrierSample& gasStart,
                 const MidpointSampler& sampleMidpoint, const std::vector<double>& stepLengths,
                 const SpeciesValues& species);

    /// Advances every particle i over stepLengths[i] without gas (no drag).
    void fly(ParticleCloud& cloud, const std::vector<double>& stepLengths,
             const SpeciesValues& species) const;

    /// Particle i's qE/m and qB/m in uniform fields (for adaptiveRungeKutta, which takes them
    /// in its own steps).
    LorentzRates ratesOf(const ParticleCloud& cloud, std::size_t i,
                         const SpeciesValues& species) const;

private:
    /// What the flow takes for particle i at x: qE/m with the body and magnetic accelerations,
    /// and Ω = qB/m.
    struct Forcing {
        Vec3 acceleration;
        Vec3 gyration;
    };
    Forcing forcingAt(const ParticleCloud& cloud, std::size_t i, const SpeciesValues& species,
                      const Vec3& x) const;
    /// Particle i's q/m [C/kg].
    double chargeToMassOf(const ParticleCloud& cloud, std::size_t i,
                          const SpeciesValues& species) const;
    /// Particle i's ρp.
    double densityOf(std::size_t i, const SpeciesValues& species) const {
        return species.alike() ? drag_.particleDensity : species.density[i];
    }
    ElectromagneticSettings fields_;
    DragParameters drag_;
    Vec3 bodyAcceleration_;
    double susceptibility_;
    /// Particle i's drag, of its own density where species differ.
    DragParameters dragOf(std::size_t i, const SpeciesValues& species) const {
        return species.alike() ? drag_ : drag_.withDensity(species.density[i]);
    }
    /// Particle i's body acceleration.
    const Vec3& accelerationOf(std::size_t i, const SpeciesValues& species) const {
        return species.alike() ? bodyAcceleration_ : species.acceleration[i];
    }
    std::vector<Vec3> midpoints_, midpointVelocities_;
    CarrierSample gasMidpoint_;
};

} // namespace slides
