// RunOutput: everything a run writes to its output directory (CASE/slides/ by default).
//
//   particles.pvd          time series for ParaView, one entry per frame
//   particles_NNNNNN.vtp   moving particles (state 0) and those that arrived (state 1)
//   carrier.vti            the carrier sampled on a lattice over the domain, for context
//   summary.json           counts, arrival statistics, speed and settings (io/summary.h)
// Every file is written under a temporary name and renamed, and the .pvd is rewritten after
// each frame, so a run stopped at any moment leaves a consistent, openable series.
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/config/scene.h"
#include "slides/integrate/stepper.h"
#include "slides/io/pvd_series.h"

#include <filesystem>
#include <nlohmann/json.hpp>

namespace slides {

class RunOutput {
public:
    /// Creates the directory, removes the frames of an earlier run there and writes
    /// carrier.vti.
    RunOutput(std::filesystem::path directory, const Scene& scene, const CarrierField& carrier);

    /// Writes the frame of the stepper's current state.
    void writeFrame(const Stepper& stepper);
    void writeSummary(const nlohmann::json& summary);

    const std::filesystem::path& directory() const { return directory_; }
    int frames() const { return frames_; }

private:
    std::filesystem::path directory_;
    PvdSeries series_;
    ParticleFieldSet fields_;
    int frames_ = 0;
    // Frame scratch: moving particles then arrivals.
    std::vector<std::uint64_t> ids_;
    std::vector<Vec3> positions_;
    std::vector<Vec3> velocities_;
    std::vector<double> radii_;
    std::vector<std::int32_t> states_;
    bool heating_;                     ///< particles carry a temperature
    std::vector<double> temperatures_; ///< [K], with heat transfer
};

} // namespace slides
