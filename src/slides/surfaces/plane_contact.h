// Contact of a moving sphere with a plane surface, found along its path over one step.
//
// A sphere of radius R touches the plane (point p, unit normal n into the gas) when its
// centre's signed distance (x − p)·n falls to R. Over a step the centre moves on the straight
// chord x0 → x1, so the first touch is at the fraction α = d0 / (d0 − d1) of the chord, with
// d = (x − p)·n − R.
//
//     surfaces { target { type plane; point (0.1 0 0); normal (-1 0 0); } }
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/surfaces/surface_settings.h"

#include <optional>

namespace slides {

/// Fraction α ∈ [0, 1] of the step at which the sphere first touches the plane, if it does;
/// a sphere already touching or behind it at the start touches at α = 0.
inline std::optional<double> planeContactFraction(const Surface& plane, const Vec3& start,
                                                  const Vec3& end, double radius) {
    const double startGap = (start - plane.point).dot(plane.normal) - radius;
    const double endGap = (end - plane.point).dot(plane.normal) - radius;
    if (endGap > 0) return std::nullopt;
    if (startGap <= 0) return 0.0;
    return startGap / (startGap - endGap);
}

} // namespace slides
