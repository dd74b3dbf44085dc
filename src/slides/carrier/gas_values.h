// GasValues: the carrier's U, k, ε and T at one place, side by side (48 bytes).
//
// A mesh's cellPoint fields are stored as one record per cell, face and point (carrier/
// foam_carrier.h), so a sample loads four records instead of four values of each field from
// separate arrays; a lattice node hands its values over in the same record. The arithmetic is
// component by component, in the order Eigen's would be for each field alone, so a sum over
// records gives bit for bit what the fields summed one by one give.
//
//     GasValues here = w0 * cell + w1 * face + w2 * point0 + w3 * point1;
#pragma once

#include "slides/core/vector.h"

#include <array>

namespace slides {

struct GasValues {
    Vec3 velocity = Vec3::Zero();    ///< U [m/s]
    std::array<double, 3> scalars{}; ///< k [m²/s²], ε [m²/s³], T [K]; zero where not given

    GasValues& operator+=(const GasValues& other) {
        velocity += other.velocity;
        for (int s = 0; s < 3; ++s) scalars[s] += other.scalars[s];
        return *this;
    }
};

inline GasValues operator*(double weight, const GasValues& values) {
    GasValues scaled;
    scaled.velocity = weight * values.velocity;
    for (int s = 0; s < 3; ++s) scaled.scalars[s] = weight * values.scalars[s];
    return scaled;
}

inline GasValues operator+(GasValues left, const GasValues& right) { return left += right; }

inline GasValues operator/(const GasValues& values, double divisor) {
    GasValues divided;
    divided.velocity = values.velocity / divisor;
    for (int s = 0; s < 3; ++s) divided.scalars[s] = values.scalars[s] / divisor;
    return divided;
}

/// The velocity of a field's value, for code written for U alone or for the records.
inline const Vec3& velocityOf(const Vec3& velocity) { return velocity; }
inline const Vec3& velocityOf(const GasValues& values) { return values.velocity; }

} // namespace slides
