#include "slides/io/hdf5_particles.h"

#include "slides/core/particle_cloud.h"
#include "slides/io/atomic_file.h"

#include <cstdio>
#include <stdexcept>
#include <system_error>

namespace slides {

namespace {

std::filesystem::path partialPath(const std::filesystem::path& directory) {
    return directory / (std::string(ParticlesHdf5::fileName) + ".partial");
}

} // namespace

std::string particlesFrameGroup(std::size_t index) {
    char group[48];
    std::snprintf(group, sizeof group, "/frames/%06zu", index);
    return group;
}

ParticlesHdf5::ParticlesHdf5(const std::filesystem::path& directory, const std::string& caseName)
    : directory_(directory) {
    file_.emplace(partialPath(directory));
    file_->writeAttribute(file_->root(), "software", "SLIDES-track");
    file_->writeAttribute(file_->root(), "version", SLIDES_VERSION);
    file_->writeAttribute(file_->root(), "case", caseName);
    file_->createGroup("/frames");
}

void ParticlesHdf5::writeFrame(double time, const ParticleFrame& frame) {
    if (!frame.consistent()) throw std::invalid_argument("particle frame arrays differ in length");
    const std::size_t count = frame.id.size();
    const std::string group = particlesFrameGroup(frames_.size());
    const Hdf5File& file = *file_;
    const Hdf5Handle created = file.createGroup(group);
    const hid_t g = created.get();
    file.writeAttribute(g, "time", time);
    file.writeDataset(g, "position", frame.position, "m");
    const auto has = [&](ParticleField field) { return frame.fields.contains(field); };
    if (has(ParticleField::id)) file.writeDataset(g, "id", frame.id, "1");
    if (has(ParticleField::velocity)) file.writeDataset(g, "velocity", frame.velocity, "m/s");
    if (has(ParticleField::diameter)) {
        scratch_.resize(count);
        for (std::size_t i = 0; i < count; ++i) scratch_[i] = particleDiameter(frame.radius[i]);
        file.writeDataset(g, "diameter", scratch_, 1, "m");
    }
    if (has(ParticleField::speed)) {
        scratch_.resize(count);
        for (std::size_t i = 0; i < count; ++i) scratch_[i] = frame.velocity[i].norm();
        file.writeDataset(g, "speed", scratch_, 1, "m/s");
    }
    if (has(ParticleField::state)) file.writeDataset(g, "state", frame.state, "1");
    if (frame.temperature && has(ParticleField::temperature))
        file.writeDataset(g, "temperature", *frame.temperature, 1, "K");
    if (frame.angularVelocity && has(ParticleField::angularVelocity))
        file.writeDataset(g, "angularVelocity", *frame.angularVelocity, "rad/s");
    if (frame.charge) file.writeDataset(g, "charge", *frame.charge, 1, "C");
    if (frame.injector) file.writeDataset(g, "injector", *frame.injector, "1");
    if (frame.density) file.writeDataset(g, "density", *frame.density, 1, "kg/m^3");
    file.flush();
    frames_.push_back({group, time, count,
                       presentFields(frame.fields, frame.temperature.has_value(),
                                     frame.angularVelocity.has_value())});
}

void ParticlesHdf5::finish(std::span<const Arrival> arrivals,
                           std::optional<std::span<const double>> density) {
    if (density && density->size() != arrivals.size())
        throw std::invalid_argument("arrival densities differ in number from the arrivals");
    const Hdf5File& file = *file_;
    const Hdf5Handle group = file.createGroup("/arrivals");
    const std::size_t count = arrivals.size();
    std::vector<std::uint64_t> ids(count);
    std::vector<std::int32_t> surfaces(count);
    std::vector<double> times(count), diameters(count);
    std::vector<Vec3> positions(count), velocities(count);
    for (std::size_t i = 0; i < count; ++i) {
        ids[i] = arrivals[i].id;
        surfaces[i] = arrivals[i].surface;
        times[i] = arrivals[i].time;
        diameters[i] = particleDiameter(arrivals[i].radius);
        positions[i] = arrivals[i].position;
        velocities[i] = arrivals[i].velocity;
    }
    file.writeDataset(group.get(), "id", ids, "1");
    file.writeDataset(group.get(), "surface", surfaces, "1");
    file.writeDataset(group.get(), "time", times, 1, "s");
    file.writeDataset(group.get(), "position", positions, "m");
    file.writeDataset(group.get(), "velocity", velocities, "m/s");
    file.writeDataset(group.get(), "diameter", diameters, 1, "m");
    if (density) file.writeDataset(group.get(), "density", *density, 1, "kg/m^3");
    file.writeAttribute(file.root(), "frames", static_cast<std::int64_t>(frames_.size()));
    file_->close();
    file_.reset();

    std::error_code error;
    std::filesystem::rename(partialPath(directory_), directory_ / fileName, error);
    if (error)
        throw OutputError("cannot rename " + partialPath(directory_).string() + " to " + fileName +
                          ": " + error.message());
    writeTextAtomically(directory_ / indexName, particlesXdmf(fileName, frames_));
}

} // namespace slides
