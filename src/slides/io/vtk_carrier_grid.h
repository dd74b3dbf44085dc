// The carrier sampled on a lattice (VTK ImageData, .vti), for context in ParaView: the gas jet
// beside the particles, e.g. as a Slice coloured by magU or with Stream Tracer on U.
//
// Point arrays U [m/s] (3 components, the active vectors) and magU [m/s] (the active scalars);
// field array TimeValue [s], which ParaView shows as the dataset's time. Binary,
// zlib-compressed, appended. The whole lattice is one batched CarrierField::sample() call.
#pragma once

#include "slides/carrier/carrier_field.h"

#include <array>
#include <filesystem>

namespace slides {

/// Samples carrier at time on pointsPerAxis lattice points spanning box (corners included; an
/// axis with one point lies at box.min) and writes the lattice atomically. Throws OutputError
/// on failure and std::invalid_argument if an axis has fewer than one point.
void writeCarrierVti(const std::filesystem::path& file, const CarrierField& carrier, const Box& box,
                     std::array<int, 3> pointsPerAxis, double time);

/// The sample writeCarrierVti writes, without writing it (the ranks of a parallel run that do
/// not write take part in the sampling so).
CarrierSample sampleCarrierLattice(const CarrierField& carrier, const Box& box,
                                   std::array<int, 3> pointsPerAxis, double time);

} // namespace slides
