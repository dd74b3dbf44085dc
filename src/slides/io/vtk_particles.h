// Particle frames as VTK XML PolyData (.vtp): one vertex per particle, so ParaView shows them
// at once (Points, or Point Gaussian scaled by `diameter`) without a Glyph filter.
//
// Point arrays: id (Int64), diameter [m], velocity [m/s] (3 components), speed [m/s],
// state (Int32: 0 moving, 1 arrived at a surface). Binary, zlib-compressed, appended.
#pragma once

#include "slides/core/vector.h"

#include <cstdint>
#include <filesystem>
#include <span>

namespace slides {

struct ParticleFrame {
    std::span<const std::uint64_t> id;
    std::span<const Vec3> position;
    std::span<const Vec3> velocity;
    std::span<const double> radius;
    std::span<const std::int32_t> state;
};

/// Writes the frame atomically (io/atomic_file.h); throws OutputError on failure.
void writeParticlesVtp(const std::filesystem::path& file, const ParticleFrame& frame);

} // namespace slides
