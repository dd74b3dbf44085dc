// PatchSampler: points uniform in area over the faces of a mesh patch (the injection model
// `patch` of integrate/injector.h), as OpenFOAM's patchInjection places its parcels.
//
// Reference: G. Turk, "Generating random points in triangles", Graphics Gems (1990): with
// uniforms u1, u2, the point (1 − √u1) a + √u1 (1 − u2) b + √u1 u2 c is uniform in the
// triangle abc. The triangle is chosen with probability ∝ its area (inverse of the cumulative
// areas), so the points are uniform over the whole patch.
//
//     injectors { inlet { model patch; patchCoeffs { patch inlet; } count 1000; rate 1e5; } }
#pragma once

#include "slides/carrier/carrier_field.h"

#include <vector>

namespace slides {

class PatchSampler {
public:
    /// The patch's faces as triangles, counter-clockwise seen from the gas
    /// (CarrierField::patchTriangles); at least one with a positive area.
    explicit PatchSampler(std::vector<PatchTriangle> triangles);

    struct Point {
        Vec3 position; ///< on the patch, moved into the gas by 1e-9 of its triangle's size
        Vec3 normal;   ///< unit normal of its triangle, into the gas
    };
    /// The point of three uniforms on [0, 1): the first picks the triangle, the others the point.
    Point draw(double uniformArea, double u1, double u2) const;
    /// Total area [m²].
    double area() const { return cumulativeArea_.back(); }

private:
    std::vector<PatchTriangle> triangles_;
    std::vector<double> cumulativeArea_; ///< of triangles [0, k]
};

} // namespace slides
