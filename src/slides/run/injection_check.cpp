#include "slides/run/injection_check.h"

#include "slides/config/scene_reader.h"
#include "slides/core/error.h"
#include "slides/integrate/injector.h"

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

constexpr int rings = 16;             // of equal area, so each point stands for an equal share
constexpr int pointsPerRing = 32;     // of the disc
constexpr int pointsOnLine = 129;     // a 2-D mesh's slot, evenly spaced across it
constexpr long latticeSamples = 4096; // sites checked at most, evenly spread over the fill order

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

/// The sites particles.count particles take on the lattice, or an even selection of them.
std::vector<Vec3> latticePoints(const Scene& scene) {
    const long count = scene.particles.count;
    const long stride = std::max(1L, count / latticeSamples);
    std::vector<Vec3> points;
    for (long id = 0; id < count; id += stride)
        points.push_back(latticeSite(scene.injection, static_cast<ParticleId>(id)));
    return points;
}

/// Refuses the start when points lie outside the mesh or the domain box given.
void requireInside(const Scene& scene, const CarrierField& carrier, std::span<const Vec3> points,
                   const std::string& key, const std::string& what) {
    const auto refuse = [&](std::size_t outside, const std::string& where) {
        std::ostringstream message;
        message << what << " is not inside " << where << ": "
                << std::lround(100.0 * static_cast<double>(outside) /
                               static_cast<double>(points.size()))
                << " % of it (" << outside << " of " << points.size()
                << " points spread evenly over it) lies outside";
        throw InputError(scene.dictionaryFile.string(), keyLine(scene.dictionaryFile, key), key,
                         message.str());
    };
    if (const std::size_t outside = countOutsideMesh(points, carrier); outside > 0)
        refuse(outside, "the OpenFOAM mesh");
    if (scene.domainFromCarrier) return; // the mesh is the domain
    if (const std::size_t outside = countOutsideBox(points, scene.domain); outside > 0)
        refuse(outside, "the domain box");
}

/// The start points of one injector of `injectors {}`: its disc (or point), or its file's rows
/// (an even selection of them).
void requireInjectorInside(const Scene& scene, const CarrierField& carrier,
                           const InjectorSettings& injector) {
    const std::string base = "injectors." + injector.name;
    if (injector.model == InjectionModel::patch) return; // on the mesh's own faces
    if (injector.givesRows()) {
        const std::size_t stride = std::max<std::size_t>(1, injector.rows.size() / latticeSamples);
        std::vector<Vec3> points;
        for (std::size_t k = 0; k < injector.rows.size(); k += stride)
            points.push_back(injector.rows[k].position);
        const bool file = injector.model == InjectionModel::file;
        requireInside(scene, carrier, points, base + (file ? ".file" : ".ensembleCoeffs"),
                      "the " + std::to_string(injector.rows.size()) + " particles of the " +
                          (file ? "file" : "ensemble"));
        return;
    }
    std::ostringstream disc;
    disc << "the disc of injector " << injector.name << " of radius " << injector.nozzle.radius
         << " m";
    requireInside(scene, carrier, discPoints(injector.nozzle, carrier.planeNormal()),
                  base + (injector.nozzle.radius > 0 ? ".radius" : ".centre"), disc.str());
}

} // namespace

void requireInjectionInside(const Scene& scene, const CarrierField& carrier) {
    for (const InjectorSettings& injector : scene.injectors)
        requireInjectorInside(scene, carrier, injector);
    if (!scene.injectors.empty()) return;
    if (scene.injection.mode == InjectionMode::lattice) {
        requireInside(scene, carrier, latticePoints(scene), "injection.latticeCoeffs.origin",
                      "the lattice of " + std::to_string(scene.particles.count) + " sites");
        return;
    }
    std::ostringstream disc;
    disc << "the nozzle disc of radius " << scene.nozzle.radius << " m";
    requireInside(scene, carrier, discPoints(scene.nozzle, carrier.planeNormal()), "nozzle.radius",
                  disc.str());
}

} // namespace slides
