#include "slides/run/nozzle_check.h"

#include "slides/config/scene_reader.h"
#include "slides/core/error.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <span>
#include <sstream>
#include <vector>

namespace slides {

namespace {

constexpr int rings = 16;         // of equal area, so each point stands for an equal share
constexpr int pointsPerRing = 32; // of the disc
constexpr int pointsOnLine = 129; // a 2-D mesh's slot, evenly spaced across it

/// Points spread evenly over the disc, or over its diameter in the plane of a 2-D carrier.
std::vector<Vec3> discPoints(const JetNozzle& nozzle, const std::optional<Vec3>& planeNormal) {
    std::vector<Vec3> points;
    const Vec3 inPlane = planeNormal ? planeNormal->cross(nozzle.axis) : Vec3::Zero();
    if (inPlane.norm() > 1e-6) {
        const Vec3 across = inPlane.normalized();
        for (int i = 0; i < pointsOnLine; ++i) {
            const double fraction = (i + 0.5) / pointsOnLine * 2 - 1;
            points.push_back(nozzle.centre + fraction * nozzle.radius * across);
        }
        return points;
    }
    const Vec3 across = nozzle.crossSpanDirection;
    const Vec3 other = nozzle.axis.cross(across);
    for (int ring = 0; ring < rings; ++ring) {
        const double radius = nozzle.radius * std::sqrt((ring + 0.5) / rings);
        for (int k = 0; k < pointsPerRing; ++k) {
            const double angle = 2 * std::numbers::pi * (k + 0.5 * (ring % 2)) / pointsPerRing;
            points.push_back(nozzle.centre +
                             radius * (std::cos(angle) * across + std::sin(angle) * other));
        }
    }
    return points;
}

std::size_t countOutsideMesh(std::span<const Vec3> points, const CarrierField& carrier) {
    if (!carrier.keepsLocations()) return 0;
    std::vector<std::int32_t> locations(points.size(), -1);
    CarrierSample sample;
    carrier.sampleFrom(points, locations, 0.0, CarrierNeeds{}, sample);
    return static_cast<std::size_t>(std::count_if(locations.begin(), locations.end(),
                                                  [](std::int32_t at) { return at <= -2; }));
}

std::size_t countOutsideBox(std::span<const Vec3> points, const Box& box) {
    return static_cast<std::size_t>(std::count_if(points.begin(), points.end(), [&](const Vec3& x) {
        return !((x.array() > box.min.array()).all() && (x.array() < box.max.array()).all());
    }));
}

[[noreturn]] void refuse(const Scene& scene, std::size_t outside, std::size_t points,
                         const std::string& where) {
    std::ostringstream message;
    message << "the nozzle disc of radius " << scene.nozzle.radius << " m is not inside " << where
            << ": " << std::lround(100.0 * outside / points) << " % of it (" << outside << " of "
            << points << " points spread evenly over it) lies outside";
    throw InputError(scene.dictionaryFile.string(), keyLine(scene.dictionaryFile, "nozzle.radius"),
                     "nozzle.radius", message.str());
}

} // namespace

void requireNozzleDiscInside(const Scene& scene, const CarrierField& carrier) {
    if (scene.injection.mode == InjectionMode::lattice) return; // the nozzle injects nothing
    const std::vector<Vec3> points = discPoints(scene.nozzle, carrier.planeNormal());
    if (const std::size_t outside = countOutsideMesh(points, carrier); outside > 0)
        refuse(scene, outside, points.size(), "the OpenFOAM mesh");
    if (scene.domainFromCarrier) return; // the mesh is the domain
    if (const std::size_t outside = countOutsideBox(points, scene.domain); outside > 0)
        refuse(scene, outside, points.size(), "the domain box");
}

} // namespace slides
