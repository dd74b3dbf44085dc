// ParticleHeating: the step loop's use of the heat-transfer models (physics/heat_transfer.h) —
// after the kinematic step, each particle's lumped temperature relaxes toward the gas
// temperature over its step, exactly for T_gas and τ_θ frozen at their step-start values.
//
//     physics { heatTransfer { model ranzMarshall; } }   // none: this does nothing
//
// michaelidesFeng (Eq. 3.29, physics/michaelides_feng.h) keeps a history memory per particle in
// ParticleCloud::modelState, after the Maxey–Riley step's block (placeState).
//
// Re = 2R |u − v|/ν uses the gas velocity the particle saw (with the turbulent fluctuation) and
// its velocity at the step start; T_gas is the carrier's temperature at the step-start
// position. Newly injected particles start at particles.injectionTemperature. Where species
// differ (integrate/injection_settings.h), each particle's own ρp and c_p set its τ_θ (and the
// rates of michaelidesFeng).
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/carrier/carrier_settings.h"
#include "slides/core/particle_cloud.h"
#include "slides/integrate/injection_settings.h"
#include "slides/integrate/species_values.h"
#include "slides/integrate/time_settings.h"
#include "slides/physics/heat_transfer.h"
#include "slides/physics/michaelides_feng.h"

#include <optional>
#include <vector>

namespace slides {

class ParticleHeating {
public:
    /// The history memory of michaelidesFeng is sized for steps of time.dt up to time.endTime at
    /// historyAccuracy (physics.history.accuracy).
    ParticleHeating(HeatTransferModel model, const FluidSettings& fluid,
                    const ParticleSettings& particles, const TimeSettings& time,
                    double historyAccuracy);

    bool on() const { return model_ != HeatTransferModel::none; }
    /// Doubles of model state per particle (michaelidesFeng's memory; 0 for the correlations).
    std::size_t stateWidth() const;
    /// Where the state starts in each particle's stretch of ParticleCloud::modelState.
    void placeState(std::size_t offset) { stateOffset_ = offset; }

    /// Advances every particle's temperature over stepLengths[i]; gas holds U (as seen) and T
    /// at the step-start positions, startVelocities the particle velocities there; species:
    /// the particles' own ρp and c_p where they differ (specificHeat held), else empty.
    void advance(ParticleCloud& cloud, const CarrierSample& gas,
                 const std::vector<Vec3>& startVelocities, const std::vector<double>& stepLengths,
                 const SpeciesValues& species) const;

private:
    HeatTransferModel model_;
    double prandtl_;
    double kinematicViscosity_;
    double thermalConductivity_;
    double particleDensity_;
    double particleSpecificHeat_;
    double injectionTemperature_;
    double fluidDensity_, fluidSpecificHeat_;
    std::optional<WindowTailLayout> memory_; ///< michaelidesFeng's history
    std::size_t stateOffset_ = 0;
};

} // namespace slides
