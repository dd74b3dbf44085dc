// SpeciesValues: each particle's own values, in cloud order, where the injectors' species differ
// (integrate/injection_settings.h, ParticleSettings::species), for the stages whose models read
// them; the stepper holds them once a step (run/stepper.h, holdSpeciesValues). Empty spans when
// the particles are alike: each model then takes its one common value, as without species.
//
//     injectors { a { ... density 2500; } b { ... density 8960; specificHeat 385;
//                                              susceptibility 0.3; } }
#pragma once

#include "slides/core/vector.h"

#include <span>

namespace slides {

struct SpeciesValues {
    std::span<const double> density;        ///< ρp [kg/m³]
    std::span<const Vec3> acceleration;     ///< gravity with buoyancy, (1 − ρf/ρp) g [m/s²]
    std::span<const double> specificHeat;   ///< c_p [J/(kg K)]; held with heat transfer only
    std::span<const double> susceptibility; ///< χm [-]; held with magnetisation only

    bool alike() const { return density.empty(); }
};

} // namespace slides
