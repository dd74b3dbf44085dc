// Output settings: what a run writes and how often (`output {}`).
//
//     output { interval 5e-4; carrierResolution (120 60 60); fields (id diameter velocity);
//              hdf5 yes; }
#pragma once

#include "slides/io/particle_fields.h"

#include <array>

namespace slides {

struct OutputSettings {
    double interval = 0;                               ///< [s] between particle frames
    std::array<int, 3> carrierResolution{};            ///< lattice points of carrier.vti per axis
    ParticleFieldSet fields = ParticleFieldSet::all(); ///< point arrays of each frame
    bool hdf5 = true; ///< also particles.h5 + particles.xmf (io/hdf5_particles.h)
};

} // namespace slides
