// FoamCaseOutline: what a case template needs to know of an OpenFOAM case — its patches with
// their type and plane, the box the carrier covers, and the inlet the particles enter through.
//
// The inlet is the patch whose name contains "inlet", else the patch (type patch) with the
// largest area-weighted inflow −U·n of the latest time's U (a jet's nozzle, not its slowly
// entraining sides). On a wedge the nozzle disc sits on the axis and reaches the patch's
// largest radius; on a 2-D mesh it is the slot's line in the plane (carrier/foam_carrier.h).
//
//     const FoamCaseOutline outline = outlineFoamCase(solvedImpingingJet);
//     outline.inlet->name == "nozzle"; outline.inlet->radius == 2e-3;
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/carrier/foam_mesh.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace slides {

enum class FoamMeshShape { threeDimensional, wedge, twoDimensional };

struct FoamPatchOutline {
    std::string name;
    PatchType type = PatchType::patch;
    Vec3 point = Vec3::Zero();         ///< area-weighted face centre; a wedge's plane: on the axis
    Vec3 inwardNormal = Vec3::UnitX(); ///< unit, into the mesh (the mean of the faces')
    bool planar = false; ///< every face's normal along inwardNormal (on a wedge: its axis)
};

/// The disc through which particles enter: on the inlet patch, along its inward normal.
struct FoamInletOutline {
    std::string name; ///< the patch
    Vec3 centre = Vec3::Zero();
    Vec3 axis = Vec3::UnitX();
    double radius = 0;
    Vec3 crossSpanDirection = Vec3::UnitY(); ///< across the axis (in the plane of a 2-D mesh)
    double inflowSpeed = 0;                  ///< area-weighted mean of −U·n [m/s]
};

struct FoamCaseOutline {
    FoamMeshShape shape = FoamMeshShape::threeDimensional;
    Box bounds;                            ///< the 3-D region the carrier covers
    std::vector<FoamPatchOutline> patches; ///< in the order of constant/polyMesh/boundary
    std::optional<FoamInletOutline> inlet;
    double largestSpeed = 0; ///< largest |U| over the cells [m/s]
    std::string time;        ///< the latest time directory's name
};

/// Reads constant/polyMesh and the latest time's U of caseDirectory; InputError as the run
/// would raise for a missing or bad mesh or field.
FoamCaseOutline outlineFoamCase(const std::filesystem::path& caseDirectory);

/// OpenFOAM's word for a patch type (patch, wall, symmetry, wedge, empty, processor).
const char* patchTypeWord(PatchType type);

} // namespace slides
