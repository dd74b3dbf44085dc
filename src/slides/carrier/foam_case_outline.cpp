#include "slides/carrier/foam_case_outline.h"

#include "slides/carrier/foam_carrier.h"
#include "slides/carrier/foam_field.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <ranges>
#include <utility>

namespace slides {

namespace {

bool nameSaysInlet(std::string name) {
    std::ranges::transform(name, name.begin(), [](unsigned char c) { return std::tolower(c); });
    return name.find("inlet") != std::string::npos;
}

/// The patch's centre, inward normal and whether it is a plane of the region the carrier covers:
/// on a wedge only a plane across the axis is one (swept about it), its point then on the axis.
FoamPatchOutline outlinePatch(const FoamMesh& mesh, const FoamPatch& patch,
                              const std::optional<WedgeFrame>& wedge) {
    FoamPatchOutline outline{.name = patch.name, .type = patch.type};
    Vec3 area = Vec3::Zero(), weightedCentre = Vec3::Zero();
    double areaMagnitude = 0;
    for (int f = patch.start; f < patch.start + patch.size; ++f) {
        const double a = mesh.faceAreas[f].norm();
        area += mesh.faceAreas[f];
        weightedCentre += a * mesh.faceCentres[f];
        areaMagnitude += a;
    }
    if (areaMagnitude <= 0 || area.norm() <= 0) return outline; // no faces (a wedge's axis)
    outline.point = weightedCentre / areaMagnitude;
    outline.inwardNormal = -area.normalized();
    outline.planar =
        std::ranges::all_of(std::views::iota(patch.start, patch.start + patch.size), [&](int f) {
            return -mesh.faceAreas[f].normalized().dot(outline.inwardNormal) > 1 - 1e-9;
        });
    if (wedge) {
        outline.planar &= std::abs(outline.inwardNormal.dot(wedge->axis)) > 1 - 1e-9;
        if (outline.planar)
            outline.point =
                wedge->origin + (outline.point - wedge->origin).dot(wedge->axis) * wedge->axis;
    }
    return outline;
}

/// Area-weighted mean of −U·n over the patch's faces; 0 where the field gives no face values.
double inflowSpeed(const FoamMesh& mesh, const FoamPatch& patch, const std::vector<Vec3>& values) {
    if (values.size() != static_cast<std::size_t>(patch.size) || patch.size == 0) return 0;
    double flux = 0, area = 0;
    for (int i = 0; i < patch.size; ++i) {
        flux -= values[i].dot(mesh.faceAreas[patch.start + i]);
        area += mesh.faceAreas[patch.start + i].norm();
    }
    return area > 0 ? flux / area : 0;
}

/// Some unit vector perpendicular to axis.
Vec3 anyPerpendicular(const Vec3& axis) {
    const Vec3 trial = std::abs(axis.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    return (trial - trial.dot(axis) * axis).normalized();
}

/// The nozzle disc on the patch: centred on it (on a wedge's axis), reaching its farthest point
/// across the axis (within the plane on a 2-D mesh).
FoamInletOutline inletDisc(const FoamCarrier& carrier, const FoamPatch& patch,
                           const FoamPatchOutline& outline, double speed) {
    const FoamMesh& mesh = carrier.mesh();
    FoamInletOutline inlet{.name = patch.name, .axis = outline.inwardNormal, .inflowSpeed = speed};
    inlet.centre = outline.point;
    inlet.crossSpanDirection = anyPerpendicular(inlet.axis);
    if (const auto& wedge = carrier.wedge()) {
        const Vec3 offset = outline.point - wedge->origin;
        inlet.centre = wedge->origin + offset.dot(wedge->axis) * wedge->axis;
        inlet.crossSpanDirection = wedge->radial;
    } else if (const auto plane = carrier.planeNormal()) {
        inlet.crossSpanDirection = inlet.axis.cross(*plane).normalized();
    }
    for (int f = patch.start; f < patch.start + patch.size; ++f)
        for (const int p : mesh.pointsOf(f)) {
            const Vec3 d = mesh.points[p] - inlet.centre;
            const double across = carrier.planeNormal()
                                      ? std::abs(d.dot(inlet.crossSpanDirection))
                                      : (d - d.dot(inlet.axis) * inlet.axis).norm();
            inlet.radius = std::max(inlet.radius, across);
        }
    return inlet;
}

} // namespace

const char* patchTypeWord(PatchType type) {
    switch (type) {
    case PatchType::patch: return "patch";
    case PatchType::wall: return "wall";
    case PatchType::symmetry: return "symmetry";
    case PatchType::wedge: return "wedge";
    case PatchType::empty: return "empty";
    case PatchType::processor: return "processor";
    }
    return "patch";
}

FoamCaseOutline outlineFoamCase(const std::filesystem::path& caseDirectory) {
    const FoamCarrier carrier(caseDirectory, FoamCarrierSettings{});
    const FoamMesh& mesh = carrier.mesh();
    const std::filesystem::path timeDirectory = foamTimeDirectory(caseDirectory, "latestTime");
    const auto velocity = readFoamVolField<Vec3>(timeDirectory, "U", mesh);

    FoamCaseOutline outline;
    outline.shape = carrier.wedge()         ? FoamMeshShape::wedge
                    : carrier.planeNormal() ? FoamMeshShape::twoDimensional
                                            : FoamMeshShape::threeDimensional;
    outline.bounds = carrier.bounds().value();
    outline.time = timeDirectory.filename().string();
    for (const Vec3& u : velocity.cells)
        outline.largestSpeed = std::max(outline.largestSpeed, u.norm());

    // The inlet: a patch named so first, then the fastest inflow; none without either.
    int inlet = -1;
    std::pair<bool, double> best{false, 0.0}; // (named inlet, inflow speed)
    for (std::size_t p = 0; p < mesh.patches.size(); ++p) {
        const FoamPatch& patch = mesh.patches[p];
        outline.patches.push_back(outlinePatch(mesh, patch, carrier.wedge()));
        if (patch.type != PatchType::patch || patch.size == 0) continue;
        const std::pair<bool, double> rank{nameSaysInlet(patch.name),
                                           inflowSpeed(mesh, patch, velocity.patchValues[p])};
        if (rank > best) {
            inlet = static_cast<int>(p);
            best = rank;
        }
    }
    if (inlet >= 0)
        outline.inlet =
            inletDisc(carrier, mesh.patches[inlet], outline.patches[inlet], best.second);
    return outline;
}

} // namespace slides
