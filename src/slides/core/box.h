// Box: an axis-aligned box, such as the domain a particle escapes by leaving.
//
//     domain { min (-0.01 -0.05 -0.05); max (0.07 0.05 0.05); }
#pragma once

#include "slides/core/vector.h"

namespace slides {

/// Axis-aligned box [m].
struct Box {
    Vec3 min = Vec3::Zero();
    Vec3 max = Vec3::Zero();
};

/// Whether the point lies inside the box (boundary included); a point that is not finite does not.
inline bool insideBox(const Box& box, const Vec3& point) {
    return (point.array() >= box.min.array()).all() && (point.array() <= box.max.array()).all();
}

} // namespace slides
