// First touch of two spheres moving on straight chords over one step.
//
// With d(s) = d₀ + s (d₁ − d₀) the separation of the centres at fraction s ∈ [0, 1] of the
// step, the spheres touch where |d(s)| = R_a + R_b: the smaller root of
// |Δ|² s² + 2 (d₀·Δ) s + |d₀|² − σ² = 0, Δ = d₁ − d₀. Spheres that already overlap at the
// start touch at s = 0. A static sphere has d₁ − d₀ equal to the moving one's chord.
#pragma once

#include "slides/core/vector.h"

#include <cmath>
#include <optional>

namespace slides {

/// Fraction of the step at which spheres with centre separations startSeparation →
/// endSeparation (a − b) first touch, if they touch while approaching.
inline std::optional<double> sweptContactFraction(const Vec3& startSeparation,
                                                  const Vec3& endSeparation,
                                                  double contactDistance) {
    const Vec3 change = endSeparation - startSeparation;
    const double c = startSeparation.squaredNorm() - contactDistance * contactDistance;
    if (c <= 0) return 0.0;
    const double b = startSeparation.dot(change);
    if (b >= 0) return std::nullopt; // moving apart over the whole chord
    const double a = change.squaredNorm();
    const double discriminant = b * b - a * c;
    if (discriminant < 0) return std::nullopt;
    const double fraction = c / (-b + std::sqrt(discriminant)); // = (−b − √disc)/a, stably
    if (fraction > 1) return std::nullopt;
    return fraction;
}

} // namespace slides
