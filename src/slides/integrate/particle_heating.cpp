#include "slides/integrate/particle_heating.h"

#include "slides/core/parallel.h"
#include "slides/physics/drag.h"

#include <cstddef>

namespace slides {

ParticleHeating::ParticleHeating(HeatTransferModel model, const FluidSettings& fluid,
                                 const ParticleSettings& particles, const TimeSettings& time,
                                 double historyAccuracy)
    : model_(model), prandtl_(prandtlNumber(fluid.density, fluid.kinematicViscosity,
                                            fluid.specificHeat, fluid.thermalConductivity)),
      kinematicViscosity_(fluid.kinematicViscosity),
      thermalConductivity_(fluid.thermalConductivity), particleDensity_(particles.density),
      particleSpecificHeat_(particles.specificHeat),
      injectionTemperature_(particles.injectionTemperature), fluidDensity_(fluid.density),
      fluidSpecificHeat_(fluid.specificHeat) {
    if (model == HeatTransferModel::michaelidesFeng)
        memory_ = WindowTailLayout::make(time.dt, time.endTime, historyAccuracy);
}

std::size_t ParticleHeating::stateWidth() const {
    return memory_ ? michaelidesFengDoubles(*memory_) : 0;
}

void ParticleHeating::advance(ParticleCloud& cloud, const CarrierSample& gas,
                              const std::vector<Vec3>& startVelocities,
                              const std::vector<double>& stepLengths,
                              const SpeciesValues& species) const {
    if (!on()) return;
    cloud.temperature.resize(cloud.size(), injectionTemperature_); // new particles
    const auto count = static_cast<std::ptrdiff_t>(cloud.size());
    const bool own = !species.specificHeat.empty();
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
    for (std::ptrdiff_t n = 0; n < count; ++n) {
        const auto i = static_cast<std::size_t>(n);
        const double radius = cloud.radius[i];
        const double density = own ? species.density[i] : particleDensity_;
        const double specificHeat = own ? species.specificHeat[i] : particleSpecificHeat_;
        if (memory_) {
            const MichaelidesFengRates rates =
                michaelidesFengRates(density, specificHeat, radius, fluidDensity_,
                                     fluidSpecificHeat_, thermalConductivity_);
            double* state = cloud.modelState.data() + i * cloud.stateWidth + stateOffset_;
            cloud.temperature[i] = advanceMichaelidesFeng(
                rates, *memory_, state, cloud.temperature[i], gas.temperature[i], stepLengths[i]);
            continue;
        }
        const double reynolds = particleReynolds((gas.velocity[i] - startVelocities[i]).norm(),
                                                 radius, kinematicViscosity_);
        const double responseTime =
            thermalResponseTime(density, specificHeat, radius,
                                nusseltNumber(model_, reynolds, prandtl_), thermalConductivity_);
        cloud.temperature[i] = relaxTemperature(cloud.temperature[i], gas.temperature[i],
                                                responseTime, stepLengths[i]);
    }
}

} // namespace slides
