// The deposit for ParaView: deposit.vtp (every stuck particle where it stuck, with its impact
// velocity) and deposit_<surface>.vti (the height map of surfaces/deposit_map.h as a
// one-pixel-thick image lying in the target plane; `height` [m] is its scalar: colour by it,
// or Warp By Scalar along the normal for a relief).
#pragma once

#include "slides/surfaces/arrival.h"
#include "slides/surfaces/deposit_map.h"
#include "slides/surfaces/surface_settings.h"

#include <filesystem>
#include <vector>

namespace slides {

/// Writes deposit.vtp and a deposit_<name>.vti per deposit surface into directory.
void writeDeposit(const std::filesystem::path& directory, const std::vector<Surface>& surfaces,
                  const std::vector<Arrival>& arrivals);

/// Writes one height map (io/vtk_writing.h: atomically, compressed).
void writeDepositMapVti(const std::filesystem::path& file, const DepositMap& map);

} // namespace slides
