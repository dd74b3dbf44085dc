// Particle frames as VTK XML PolyData (.vtp): one vertex per particle, so ParaView shows them
// at once (Points, or Point Gaussian scaled by `diameter`) without a Glyph filter.
//
// Point arrays (those in the frame's field set, io/particle_fields.h): id (Int64), diameter [m],
// velocity [m/s] (3 components), speed [m/s], state (Int32, ParticleState: 0 active,
// 1 arrived, 2 escaped), temperature [K] (only when the frame has temperatures: heat transfer
// on), injector (Int32, the index of the injector in `injectors {}`, when there are several);
// speed is the active scalar when written.
// Binary, zlib-compressed, appended. A frame without particles is a valid empty dataset.
// readParticlesVtp reads a frame back, value for value (a restart rebuilds the HDF5 frames
// before its checkpoint from them, io/checkpoint.h).
#pragma once

#include "slides/core/vector.h"
#include "slides/io/particle_fields.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <vector>

namespace slides {

/// One frame, one entry per particle in every span (all of the same length).
struct ParticleFrame {
    std::span<const std::uint64_t> id;
    std::span<const Vec3> position;                    ///< [m]
    std::span<const Vec3> velocity;                    ///< [m/s]
    std::span<const double> radius;                    ///< [m]
    std::span<const std::int32_t> state;               ///< ParticleState values
    ParticleFieldSet fields = ParticleFieldSet::all(); ///< which point arrays to write
    std::optional<std::span<const double>> temperature = std::nullopt;   ///< [K]; none: no heating
    std::optional<std::span<const Vec3>> angularVelocity = std::nullopt; ///< [rad/s]; none: no ω
    std::optional<std::span<const double>> charge = std::nullopt;        ///< q [C]; none: uncharged
    /// Index of the injector each particle came from; none: one injector.
    std::optional<std::span<const std::int32_t>> injector = std::nullopt;
    /// Each particle's density ρp [kg/m³]; none: the particles are alike.
    std::optional<std::span<const double>> density = std::nullopt;

    /// Whether every array holds one entry per particle.
    bool consistent() const {
        const std::size_t count = id.size();
        return position.size() == count && velocity.size() == count && radius.size() == count &&
               state.size() == count && (!temperature || temperature->size() == count) &&
               (!angularVelocity || angularVelocity->size() == count) &&
               (!charge || charge->size() == count) && (!injector || injector->size() == count) &&
               (!density || density->size() == count);
    }
};

/// Writes the frame atomically (io/atomic_file.h); throws OutputError on failure and
/// std::invalid_argument if the spans differ in length.
void writeParticlesVtp(const std::filesystem::path& file, const ParticleFrame& frame);

/// A frame owning one entry per particle in every array: read back from its .vtp file, or
/// gathered from several sources (a run's moving particles and arrivals). An array
/// the file does not hold (not in output.fields) is filled so that the frame writes the same
/// values again: velocity (speed, 0, 0) where only the speed was written (√(s²) = s exactly in
/// IEEE arithmetic), zero otherwise.
struct StoredParticleFrame {
    std::vector<std::uint64_t> id;
    std::vector<Vec3> position, velocity;
    std::vector<double> radius;
    std::vector<std::int32_t> state;
    std::vector<double> temperature;
    std::vector<Vec3> angularVelocity;
    std::vector<double> charge;

    /// The frame to write again: temperature with heating, ω with spinning, q when charged.
    ParticleFrame view(ParticleFieldSet fields, bool heating, bool spinning,
                       bool charged = false) const;
};

/// Reads a frame that writeParticlesVtp wrote. Throws InputError naming the file when it cannot
/// be read whole.
StoredParticleFrame readParticlesVtp(const std::filesystem::path& file);

} // namespace slides
