#include "slides/io/run_output.h"

#include "slides/core/error.h"
#include "slides/integrate/injection_settings.h"
#include "slides/io/atomic_file.h"
#include "slides/io/checkpoint.h"
#include "slides/io/vtk_carrier_grid.h"
#include "slides/io/vtk_particles.h"

#include <charconv>
#include <cstdio>
#include <string_view>
#include <system_error>

namespace slides {

namespace {

std::string frameFileName(std::size_t index) {
    char name[48];
    std::snprintf(name, sizeof name, "particles_%06zu.vtp", index);
    return name;
}

/// Creates directory and removes what an earlier run left there: its particle files and
/// checkpoint; on a restart only the frames after the `kept` ones and the finished HDF5 files
/// (the restart kept particles.h5.partial's first frames); and the temporaries of runs killed
/// while writing.
std::filesystem::path prepared(std::filesystem::path directory, std::optional<std::size_t> kept) {
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error)
        throw OutputError("cannot create output directory " + directory.string() + ": " +
                          error.message());
    removeStaleTemporaries(directory);
    const std::string partial = std::string(ParticlesHdf5::fileName) + ".partial";
    for (const auto& entry : std::filesystem::directory_iterator(directory)) {
        const std::string name = entry.path().filename().string();
        bool stale = name == ParticlesHdf5::fileName || name == ParticlesHdf5::indexName;
        if (name.starts_with("particles_") && name.ends_with(".vtp")) {
            const std::string_view digits(name.data() + 10, name.size() - 14);
            std::size_t index = 0;
            const auto parsed = std::from_chars(digits.begin(), digits.end(), index);
            stale = !kept || parsed.ptr != digits.end() || index >= *kept;
        }
        if (!kept) stale = stale || name == partial || name == checkpointFileName;
        // The deposit is written when a run finishes: any here is an earlier run's.
        stale = stale || name == "deposit.vtp" ||
                (name.starts_with("deposit_") && name.ends_with(".vti"));
        if (stale) std::filesystem::remove(entry.path());
    }
    return directory;
}

} // namespace

RunOutput::RunOutput(std::filesystem::path directory, const RunOutputSettings& settings,
                     const std::vector<FrameRecord>* resumed)
    : directory_(
          prepared(std::move(directory), resumed ? std::optional(resumed->size()) : std::nullopt)),
      carrierResolution_(settings.output.carrierResolution), series_(directory_ / "particles.pvd"),
      fields_(settings.output.fields), heating_(settings.temperature), spinning_(settings.spin),
      electromagnetic_(settings.electromagnetic), injectorIds_(settings.injectorIds),
      densityOf_(settings.densityOf) {
    if (resumed) {
        frames_ = *resumed;
        std::vector<std::pair<double, std::string>> series;
        for (std::size_t n = 0; n < frames_.size(); ++n)
            series.emplace_back(frames_[n].time, frameFileName(n));
        series_.resume(series);
    }
    if (settings.output.hdf5) {
        hdf5_.emplace(directory_, std::filesystem::absolute(settings.caseDirectory).string());
        // A restart writes its kept frames again, read back from their .vtp files (written
        // whole, under a temporary name): a run killed inside an HDF5 write may leave
        // particles.h5.partial unreadable, and the checkpoint holds no frames.
        for (std::size_t n = 0; n < frames_.size(); ++n) {
            const StoredParticleFrame stored = readParticlesVtp(directory_ / frameFileName(n));
            if (stored.id.size() != frames_[n].count)
                throw InputError((directory_ / frameFileName(n)).string(), 0, "",
                                 "holds " + std::to_string(stored.id.size()) +
                                     " particles, the checkpoint counts " +
                                     std::to_string(frames_[n].count) + "; cannot restart");
            ParticleFrame frame = stored.view(fields_, heating_, spinning_, electromagnetic_.on());
            std::vector<std::int32_t> injectors;
            std::vector<double> densities;
            attachInjectors(frame, injectors, densities);
            hdf5_->writeFrame(frames_[n].time, frame);
        }
    }
}

void RunOutput::writeCarrier(const CarrierField& carrier, const Box& domain) const {
    writeCarrierVti(directory_ / "carrier.vti", carrier, domain, carrierResolution_, 0.0);
}

void RunOutput::writeFrame(const RunSnapshot& snapshot) {
    const ParticleCloud& cloud = snapshot.cloud;
    // The moving particles (state active), then the arrivals (state arrived). Without arrivals
    // the frame reads the cloud's arrays in place; with them it reads copies held for this
    // frame only, so that no particle's data is held twice between frames.
    StoredParticleFrame gathered;
    gathered.state.assign(cloud.size(), static_cast<std::int32_t>(ParticleState::active));
    ParticleFrame frame{cloud.id,     cloud.position, cloud.velocity,
                        cloud.radius, gathered.state, fields_};
    if (heating_) frame.temperature = cloud.temperature;
    if (spinning_) frame.angularVelocity = cloud.angularVelocity;
    if (electromagnetic_.on()) frame.charge = cloud.charge;
    if (!snapshot.arrivals.empty()) {
        gathered.id.assign(cloud.id.begin(), cloud.id.end());
        gathered.position.assign(cloud.position.begin(), cloud.position.end());
        gathered.velocity.assign(cloud.velocity.begin(), cloud.velocity.end());
        gathered.radius.assign(cloud.radius.begin(), cloud.radius.end());
        gathered.temperature.assign(cloud.temperature.begin(), cloud.temperature.end());
        gathered.angularVelocity.assign(cloud.angularVelocity.begin(), cloud.angularVelocity.end());
        gathered.charge.assign(cloud.charge.begin(), cloud.charge.end());
        for (const auto& arrival : snapshot.arrivals) {
            gathered.id.push_back(arrival.id);
            gathered.position.push_back(arrival.position);
            gathered.velocity.push_back(arrival.velocity);
            gathered.radius.push_back(arrival.radius);
            gathered.state.push_back(static_cast<std::int32_t>(ParticleState::arrived));
            gathered.temperature.push_back(arrival.temperature);
            gathered.angularVelocity.push_back(arrival.angularVelocity);
            if (electromagnetic_.on())
                gathered.charge.push_back(electromagnetic_.chargeOf(arrival.radius, arrival.id));
        }
        frame = gathered.view(fields_, heating_, spinning_, electromagnetic_.on());
    }
    std::vector<std::int32_t> injectors;
    std::vector<double> densities;
    attachInjectors(frame, injectors, densities);
    const std::string name = frameFileName(frames_.size());
    writeParticlesVtp(directory_ / name, frame);
    const double time = snapshot.counters.time;
    if (hdf5_) hdf5_->writeFrame(time, frame);
    series_.add(time, name);
    frames_.push_back({time, frame.id.size()});
}

void RunOutput::attachInjectors(ParticleFrame& frame, std::vector<std::int32_t>& injectors,
                                std::vector<double>& densities) const {
    if (injectorIds_.firstIds.empty()) return;
    injectors.resize(frame.id.size());
    for (std::size_t i = 0; i < frame.id.size(); ++i)
        injectors[i] = injectorIds_.injectorOf(frame.id[i]);
    frame.injector = injectors;
    if (!densityOf_) return;
    densities.resize(frame.id.size());
    for (std::size_t i = 0; i < frame.id.size(); ++i) densities[i] = densityOf_(frame.id[i]);
    frame.density = densities;
}

void RunOutput::finish(const RunSnapshot& snapshot, const nlohmann::json& summary) {
    if (hdf5_) {
        std::vector<double> densities;
        if (densityOf_)
            for (const Arrival& arrival : snapshot.arrivals)
                densities.push_back(densityOf_(arrival.id));
        hdf5_->finish(snapshot.arrivals, densityOf_
                                             ? std::optional<std::span<const double>>(densities)
                                             : std::nullopt);
    }
    writeTextAtomically(directory_ / "summary.json", summary.dump(2) + "\n");
}

} // namespace slides
