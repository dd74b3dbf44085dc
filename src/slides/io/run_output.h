// RunOutput: everything a run writes to its output directory (CASE/slides/ by default).
//
//   particles.pvd          time series for ParaView, one entry per frame
//   particles_NNNNNN.vtp   moving particles (state 0) and those that arrived (state 1)
//   carrier.vti            the carrier sampled on a lattice over the domain, for context
//   summary.json           counts, arrival statistics, deposit metrics, speed and settings
//                          (io/summary.h)
//   deposit.vtp, deposit_<surface>.vti   the stuck particles and the deposit's height map,
//                          with deposit surfaces (io/vtk_deposit.h)
//   particles.h5, .xmf     every frame and the arrivals in HDF5 (io/hdf5_particles.h), when
//                          output.hdf5 is on
// Every file is written under a temporary name and renamed, and the .pvd is rewritten after
// each frame, so a run stopped at any moment leaves a consistent, openable series.
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/integrate/injection_settings.h"
#include "slides/io/frame_record.h"
#include "slides/io/hdf5_particles.h"
#include "slides/io/output_settings.h"
#include "slides/io/pvd_series.h"
#include "slides/io/run_snapshot.h"
#include "slides/physics/electromagnetic.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>

namespace slides {

/// What a run's frames hold, from its resolved settings.
struct RunOutputSettings {
    OutputSettings output;
    std::filesystem::path caseDirectory; ///< named in particles.h5
    bool temperature = false;            ///< particles carry a temperature (heat transfer)
    bool spin = false;                   ///< particles carry a spin ω
    /// The particles' charges (physics/electromagnetic.h): an arrival's is its radius's.
    ElectromagneticSettings electromagnetic;
    /// The particle ids of the injectors of `injectors {}`; none: no injector array.
    InjectorIds injectorIds;
    /// The density of particle id [kg/m³] when the particles differ (a `density` array in the
    /// frames and the arrivals); empty when they are alike.
    std::function<double(std::uint64_t)> densityOf;
};

class RunOutput {
public:
    /// Creates the directory, removes the particle files, deposit and checkpoint of an earlier
    /// run there. With `resumed` (a restart, io/checkpoint.h), continues after those frames
    /// instead: the later frames of the interrupted run are removed, the series rewritten with
    /// the earlier ones, and particles.h5.partial written anew with them (read back from their
    /// .vtp files; InputError naming a frame file that cannot be read).
    RunOutput(std::filesystem::path directory, const RunOutputSettings& settings,
              const std::vector<FrameRecord>* resumed = nullptr);

    /// Writes carrier.vti: the carrier sampled at time 0 on output.carrierResolution points
    /// over domain.
    void writeCarrier(const CarrierField& carrier, const Box& domain) const;
    /// Writes the frame of the run's state.
    void writeFrame(const RunSnapshot& snapshot);
    /// Completes the HDF5 file with the arrivals and writes summary.json: the run is over.
    void finish(const RunSnapshot& snapshot, const nlohmann::json& summary);

    const std::filesystem::path& directory() const { return directory_; }
    const std::vector<FrameRecord>& frames() const { return frames_; }

private:
    /// With several injectors, frame's `injector` array from its ids, held in `injectors`.
    /// The frame's injector array, and with differing species its density array.
    void attachInjectors(ParticleFrame& frame, std::vector<std::int32_t>& injectors,
                         std::vector<double>& densities) const;

    std::filesystem::path directory_;
    std::array<int, 3> carrierResolution_;
    PvdSeries series_;
    std::optional<ParticlesHdf5> hdf5_;
    ParticleFieldSet fields_;
    std::vector<FrameRecord> frames_;
    bool heating_;  ///< particles carry a temperature
    bool spinning_; ///< particles carry a spin ω
    ElectromagneticSettings electromagnetic_;
    InjectorIds injectorIds_;
    std::function<double(std::uint64_t)> densityOf_;
};

} // namespace slides
