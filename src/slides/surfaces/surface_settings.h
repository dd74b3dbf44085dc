// Surface settings: one surface of `surfaces {}` — a sink, a wall or a deposition target, a
// plane of the dictionary or a wall patch of the OpenFOAM mesh (surfaces/patch_wall.h); the
// interactions' name table is collide/collision_settings.h's surfaceInteractionNames().
//
//     surfaces { target { type plane; point (0.06 0 0); normal (-1 0 0); interaction deposit;
//                         material { bulkModulus 1.6e11; shearModulus 8e10; } } }
#pragma once

#include "slides/collide/collision_settings.h"
#include "slides/core/vector.h"
#include "slides/physics/contact_pair.h"
#include "slides/surfaces/erosion_settings.h"

#include <algorithm>
#include <string>
#include <vector>

namespace slides {

struct Surface {
    std::string name;
    /// The plane; for a patch, its mean plane (area-weighted centroid and normal), which the
    /// deposit's metrics and map use (surfaces/patch_wall.h, placePatchSurfaces).
    Vec3 point = Vec3::Zero();
    Vec3 normal = Vec3::UnitX(); ///< unit, pointing into the gas side
    MaterialSettings material;
    SurfaceInteraction interaction = SurfaceInteraction::absorb;
    std::string patch;       ///< the mesh patch it is; empty for a plane
    ErosionSettings erosion; ///< the layer, for interaction erode
};

/// Whether the particles carry a spin ω: the spin term (physics.spin), or contacts with friction
/// that change it (collisions, surfaces that rebound or deposit).
inline bool tracksSpin(bool spinTerm, const CollisionSettings& collisions,
                       const std::vector<Surface>& surfaces) {
    return spinTerm || collisions.model != CollisionModel::none ||
           std::any_of(surfaces.begin(), surfaces.end(), [](const Surface& s) {
               return s.interaction != SurfaceInteraction::absorb;
           });
}

} // namespace slides
