// XDMF 2 index of the particle frames in particles.h5 (io/hdf5_particles.h): a temporal
// collection with one Polyvertex grid per frame, whose geometry and attributes point at the
// frame's HDF5 datasets, so ParaView's Xdmf reader shows the series without conversion.
#pragma once

#include "slides/io/particle_fields.h"

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace slides {

/// What the index needs to know of one frame written to HDF5.
struct XdmfFrame {
    std::string group;     ///< e.g. "/frames/000003"
    double time = 0;       ///< [s]
    std::size_t count = 0; ///< particles in the frame
    ParticleFieldSet fields;
};

/// The XDMF document for the frames of hdf5File (a name relative to the .xmf file's folder).
/// Frames without particles are left out: an empty Polyvertex grid is not valid XDMF.
std::string particlesXdmf(std::string_view hdf5File, std::span<const XdmfFrame> frames);

} // namespace slides
