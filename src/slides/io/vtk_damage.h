// DamageOutput: the damage grids of the surfaces that erode (surfaces/erosion_grid.h,
// Section 5.2), written per frame and at the end of a run.
//
//   damage_<surface>.pvd, damage_<surface>_NNNNNN.vti   per frame: the layer's grid with point
//                          arrays `damage` (impacts with Σ > 0, Eq. 5.6) and `peakSigmaEq`
//                          (the largest σ_eq so far, Eq. 5.5) [Pa], for ParaView
//   damage.h5              at the end: /<surface>/damage, peakSigmaEq (x fastest, then y,
//                          then depth), centreLineTime [s], centreLineSigmaEq (impact × depth)
// and the summary's `erosion` section: impacts, damaged volume, accumulated damage (the counts'
// sum over the grid points), the peak σ_eq across the
// thickness on the centre line (Fig. 5.6's points).
#pragma once

#include "slides/io/pvd_series.h"
#include "slides/surfaces/erosion_grid.h"
#include "slides/surfaces/surface_settings.h"

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

namespace slides {

/// Writes grid's frame as a .vti image in the layer's frame (VTK's direction matrix).
void writeDamageVti(const std::filesystem::path& file, const ErosionGrid& grid, double time);

class DamageOutput {
public:
    /// Into directory, for the surfaces whose interaction is erode.
    DamageOutput(std::filesystem::path directory, const std::vector<Surface>& surfaces);

    /// Writes the frame at time of every eroding surface's grid (one per surface, empty for the
    /// others).
    void writeFrame(double time, const std::vector<std::optional<ErosionGrid>>& grids);
    /// Writes damage.h5; returns the summary's erosion section (null without eroding surfaces).
    nlohmann::json finish(const std::vector<std::optional<ErosionGrid>>& grids) const;

    bool any() const { return !series_.empty(); }

private:
    std::filesystem::path directory_;
    std::vector<std::string> names_;
    std::vector<std::optional<PvdSeries>> series_; ///< per surface; empty for those not eroding
    std::size_t frames_ = 0;
};

} // namespace slides
