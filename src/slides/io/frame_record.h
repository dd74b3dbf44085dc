// FrameRecord: what a run remembers of each particle frame it wrote, so that a checkpoint can
// restore the series (particles.pvd, the HDF5 frames and their XDMF index) on restart.
#pragma once

#include <cstddef>

namespace slides {

struct FrameRecord {
    double time = 0;       ///< [s]
    std::size_t count = 0; ///< particles in the frame (moving and arrived)
};

} // namespace slides
