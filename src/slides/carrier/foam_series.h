// FoamSeries: the written time directories of an OpenFOAM case as the time series of a carrier,
// on its fixed mesh (carrier/foam_carrier.h samples it).
//
// Reference: linear interpolation in time between the two levels that bracket t
// (carrier/time_levels.h) of U, k, ε and T; the point values of each level come from its cells
// by the weights of carrier/foam_interpolation.h, so one location of a point serves both levels.
// At most three levels are held: the two around t (three when a written time falls inside a
// step) and the next one, read ahead on a background thread while the particles move. Refused
// with an error naming the directory: fewer than two levels in the range, a level missing a
// field the first one has, a polyMesh inside a time directory (moving or changing meshes are not
// supported).
//
//     carrier { type foamField; foamFieldCoeffs { times (0 0.5); cycle 0.5; } }   // or times all;
#pragma once

#include "slides/carrier/foam_interpolation.h"
#include "slides/carrier/time_levels.h"

#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace slides {

struct FoamSeriesSettings {
    std::optional<std::pair<double, double>> range; ///< written times start…end; all when empty
    std::optional<double> cycle;                    ///< period of a periodic replay [s]
    bool readAhead = true; ///< read the next level on a background thread while particles move
};

/// One written time: U, and k, ε and T where the series has them, as records (carrier/
/// gas_records.h).
using FoamLevel = InterpolableField<GasValues>;

class FoamSeries {
public:
    FoamSeries(const std::filesystem::path& caseDirectory, const FoamSeriesSettings& settings,
               const FoamMesh& mesh);

    /// Holds the levels run times in [start, end] need (carrier/time_levels.h); InputError
    /// naming the last directory when end lies beyond the series without a cycle.
    void hold(double start, double end);
    /// The levels around run time t and their weights.
    LevelCache<FoamLevel>::Pair at(double time);

    /// Whether the levels hold k, ε or T (in the order of GasValues::scalars).
    bool has(std::size_t scalar) const { return hasScalar_[scalar]; }
    const std::filesystem::path& firstDirectory() const { return directories_.front(); }
    std::size_t levelCount() const { return directories_.size(); }
    /// Levels in memory now (at most three while a run steps no longer than the write interval).
    std::size_t heldCount() const { return cache_->heldCount(); }

private:
    std::shared_ptr<const FoamLevel> read(std::size_t index) const;

    const FoamMesh& mesh_;
    PointWeights weights_;
    std::vector<std::filesystem::path> directories_;
    std::array<bool, 3> hasScalar_{};
    std::unique_ptr<LevelCache<FoamLevel>> cache_;
};

} // namespace slides
