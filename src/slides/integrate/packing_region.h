// PackingRegion: the box or cylinder a packed ensemble fills (integrate/ensemble.h), with the
// tests the packing algorithms need: whether a sphere lies inside, the separation of two centres
// (the minimum image across a periodic box's faces), and how to hold a moving sphere inside.
//
// Reference: Section 4.3 (hard walls, or periodic boundaries as in Lubachevsky & Stillinger
// 1990).
//
//     ensembleCoeffs { shape box; min (0 0 0); max (1e-3 1e-3 1e-3); periodic no; }
//     ensembleCoeffs { shape cylinder; length 2e-3; }  // the injector's centre, axis, radius
#pragma once

#include "slides/core/vector.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string_view>

namespace slides {

enum class PackingShape { box, cylinder };

struct PackingShapeName {
    PackingShape value;
    std::string_view name;
};

constexpr std::array<PackingShapeName, 2> packingShapeNames() {
    return {{{PackingShape::box, "box"}, {PackingShape::cylinder, "cylinder"}}};
}

struct PackingRegion {
    PackingShape shape = PackingShape::box;
    Vec3 lower = Vec3::Zero(); ///< box: lower corner [m]
    Vec3 upper = Vec3::Zero(); ///< box: upper corner [m]
    /// box: the spheres may cross the faces, clear of each other's periodic images (a sample of
    /// a bulk packing); else the faces are walls and every sphere lies wholly inside.
    bool periodic = false;
    Vec3 base = Vec3::Zero();  ///< cylinder: centre of its base disc [m]
    Vec3 axis = Vec3::UnitX(); ///< cylinder: unit axis, from the base
    double radius = 0;         ///< cylinder [m]
    double length = 0;         ///< cylinder [m]

    double volume() const {
        return shape == PackingShape::box ? (upper - lower).prod()
                                          : std::numbers::pi * radius * radius * length;
    }

    /// Corners of the box that holds the region.
    Vec3 boundsLower() const { return shape == PackingShape::box ? lower : cylinderCorner(-1); }
    Vec3 boundsUpper() const { return shape == PackingShape::box ? upper : cylinderCorner(1); }

    /// How far centre lies inside the region's walls (< 0: outside); a periodic box has none.
    double depthInside(const Vec3& centre) const {
        if (shape == PackingShape::box) {
            if (periodic) return std::numeric_limits<double>::infinity();
            return std::min((centre - lower).minCoeff(), (upper - centre).minCoeff());
        }
        const Vec3 offset = centre - base;
        const double along = offset.dot(axis);
        const double across = (offset - along * axis).norm();
        return std::min({along, length - along, radius - across});
    }

    /// Whether a sphere of the radius at centre lies inside (periodic: its centre in the box).
    bool holds(const Vec3& centre, double sphereRadius) const {
        if (shape == PackingShape::box && periodic)
            return (centre.array() >= lower.array()).all() &&
                   (centre.array() < upper.array()).all();
        return depthInside(centre) >= sphereRadius;
    }

    /// from − to, across a periodic box's faces the shortest of its images.
    Vec3 separation(const Vec3& from, const Vec3& to) const {
        Vec3 d = from - to;
        if (periodic) {
            const Vec3 size = upper - lower;
            for (int a = 0; a < 3; ++a) // |from − to| < size: one image away at most
                d[a] += size[a] * (double(d[a] < -0.5 * size[a]) - double(d[a] > 0.5 * size[a]));
        }
        return d;
    }

    /// Brings a moving sphere back: into a periodic box through the opposite face, or off a
    /// wall it has crossed, its velocity's normal part reversed (an elastic wall).
    void confine(Vec3& centre, Vec3& velocity, double sphereRadius) const {
        if (shape == PackingShape::box) {
            const Vec3 size = upper - lower;
            for (int a = 0; a < 3; ++a) {
                if (periodic) {
                    centre[a] -= size[a] * std::floor((centre[a] - lower[a]) / size[a]);
                    if (centre[a] >= upper[a]) centre[a] = lower[a]; // rounding at the face
                } else if (centre[a] < lower[a] + sphereRadius) {
                    centre[a] = lower[a] + sphereRadius;
                    velocity[a] = std::abs(velocity[a]);
                } else if (centre[a] > upper[a] - sphereRadius) {
                    centre[a] = upper[a] - sphereRadius;
                    velocity[a] = -std::abs(velocity[a]);
                }
            }
            return;
        }
        const Vec3 offset = centre - base;
        double along = offset.dot(axis);
        const double alongVelocity = velocity.dot(axis);
        if (along < sphereRadius) {
            along = sphereRadius;
            if (alongVelocity < 0) velocity -= 2 * alongVelocity * axis;
        } else if (along > length - sphereRadius) {
            along = length - sphereRadius;
            if (alongVelocity > 0) velocity -= 2 * alongVelocity * axis;
        }
        Vec3 across = offset - offset.dot(axis) * axis;
        const double reach = radius - sphereRadius, distance = across.norm();
        if (distance > reach && distance > 0) {
            const Vec3 outward = across / distance;
            across = outward * reach;
            const double outwardVelocity = velocity.dot(outward);
            if (outwardVelocity > 0) velocity -= 2 * outwardVelocity * outward;
        }
        centre = base + along * axis + across;
    }

private:
    /// The corner (side −1 lower, +1 upper) of the cylinder's bounding box.
    Vec3 cylinderCorner(int side) const {
        Vec3 corner;
        for (int a = 0; a < 3; ++a) {
            const double rim = radius * std::sqrt(std::max(0.0, 1 - axis[a] * axis[a]));
            const double ends[2] = {base[a], base[a] + length * axis[a]};
            corner[a] =
                side < 0 ? std::min(ends[0], ends[1]) - rim : std::max(ends[0], ends[1]) + rim;
        }
        return corner;
    }
};

} // namespace slides
