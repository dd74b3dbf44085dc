#include "slides/run/run_limits.h"

#include "slides/config/scene_reader.h"
#include "slides/core/error.h"

#include <sstream>

#include <unistd.h>

namespace slides {

namespace {

// The least memory each needs: a particle's id, position, velocity and radius; a carrier grid
// point's position and sampled velocity.
constexpr double bytesPerParticle = 8 + 24 + 24 + 8;
constexpr double bytesPerGridPoint = 24 + 24;

double physicalMemory() {
    return static_cast<double>(sysconf(_SC_PHYS_PAGES)) *
           static_cast<double>(sysconf(_SC_PAGESIZE));
}

[[noreturn]] void refuse(const Scene& scene, const std::string& key, const std::string& message) {
    throw InputError(scene.dictionaryFile.string(), keyLine(scene.dictionaryFile, key), key,
                     message);
}

void requireFitsInMemory(const Scene& scene, const std::string& key, double bytes,
                         const std::string& what) {
    const double memory = physicalMemory();
    if (!(bytes > memory)) return;
    std::ostringstream message;
    message << what << " need at least " << bytes << " bytes, more than the machine's memory ("
            << memory << " bytes)";
    refuse(scene, key, message.str());
}

/// Refuses at key a run of count steps or frames (things) past its limit.
void requireCountWithin(const Scene& scene, const std::string& key, double count, double limit,
                        const char* things, const char* verb) {
    if (!(count > limit)) return;
    std::ostringstream message;
    message << "gives " << count << " " << things << " to time.endTime " << scene.time.endTime
            << " s, more than the " << limit << " a run may " << verb;
    refuse(scene, key, message.str());
}

} // namespace

void requireRunWithinLimits(const Scene& scene) {
    requireCountWithin(scene, "time.dt", scene.time.endTime / scene.time.dt, maximumSteps, "steps",
                       "take");
    requireCountWithin(scene, "output.interval", scene.time.endTime / scene.output.interval,
                       maximumFrames, "frames", "write");
    requireFitsInMemory(scene, "particles.count",
                        static_cast<double>(scene.particles.count) * bytesPerParticle,
                        std::to_string(scene.particles.count) + " particles");
    const auto& grid = scene.output.carrierResolution;
    const double gridPoints = static_cast<double>(grid[0]) * grid[1] * grid[2];
    if (scene.carrier.type != CarrierType::none)
        requireFitsInMemory(scene, "output.carrierResolution", gridPoints * bytesPerGridPoint,
                            "the carrier grid's " + std::to_string(grid[0]) + "×" +
                                std::to_string(grid[1]) + "×" + std::to_string(grid[2]) +
                                " points");
}

} // namespace slides
