#include "slides/io/run_output.h"

#include "slides/io/atomic_file.h"
#include "slides/io/vtk_carrier_grid.h"
#include "slides/io/vtk_particles.h"

#include <cstdio>
#include <system_error>

namespace slides {

namespace {

std::filesystem::path prepared(std::filesystem::path directory) {
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error)
        throw OutputError("cannot create output directory " + directory.string() + ": " +
                          error.message());
    // Frames of an earlier run would otherwise mix with this one's in a file browser.
    for (const auto& entry : std::filesystem::directory_iterator(directory)) {
        const std::string name = entry.path().filename().string();
        if (name.starts_with("particles_") && name.ends_with(".vtp"))
            std::filesystem::remove(entry.path());
    }
    return directory;
}

} // namespace

RunOutput::RunOutput(std::filesystem::path directory, const Scene& scene,
                     const CarrierField& carrier)
    : directory_(prepared(std::move(directory))), series_(directory_ / "particles.pvd"),
      fields_(scene.output.fields),
      heating_(scene.physics.heatTransfer != HeatTransferModel::none) {
    writeCarrierVti(directory_ / "carrier.vti", carrier, scene.domain,
                    scene.output.carrierResolution, 0.0);
}

void RunOutput::writeFrame(const Stepper& stepper) {
    const ParticleCloud& cloud = stepper.cloud();
    ids_.assign(cloud.id.begin(), cloud.id.end());
    positions_.assign(cloud.position.begin(), cloud.position.end());
    velocities_.assign(cloud.velocity.begin(), cloud.velocity.end());
    radii_.assign(cloud.radius.begin(), cloud.radius.end());
    states_.assign(cloud.size(), static_cast<std::int32_t>(ParticleState::active));
    temperatures_.assign(cloud.temperature.begin(), cloud.temperature.end());
    for (const auto& arrival : stepper.arrivals()) {
        ids_.push_back(arrival.id);
        positions_.push_back(arrival.position);
        velocities_.push_back(arrival.velocity);
        radii_.push_back(arrival.radius);
        states_.push_back(static_cast<std::int32_t>(ParticleState::arrived));
        temperatures_.push_back(arrival.temperature);
    }
    char name[32];
    std::snprintf(name, sizeof name, "particles_%06d.vtp", frames_);
    ParticleFrame frame{ids_, positions_, velocities_, radii_, states_, fields_};
    if (heating_) frame.temperature = temperatures_;
    writeParticlesVtp(directory_ / name, frame);
    series_.add(stepper.time(), name);
    ++frames_;
}

void RunOutput::writeSummary(const nlohmann::json& summary) {
    writeTextAtomically(directory_ / "summary.json", summary.dump(2) + "\n");
}

} // namespace slides
