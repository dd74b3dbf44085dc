// The carrier sampled on a lattice (VTK ImageData, .vti), for context in ParaView: the gas jet
// beside the particles. Point arrays U [m/s] (3 components) and magU [m/s]. One batched
// sample() call for the whole lattice.
#pragma once

#include "slides/carrier/carrier_field.h"

#include <array>
#include <filesystem>

namespace slides {

/// Samples carrier at time on pointsPerAxis lattice points spanning box (corners included)
/// and writes the lattice atomically; throws OutputError on failure.
void writeCarrierVti(const std::filesystem::path& file, const CarrierField& carrier,
                     const Box& box, std::array<int, 3> pointsPerAxis, double time);

} // namespace slides
