// PatchSampler: points uniform in area over the faces of a mesh patch (the injection model
// `patch` of integrate/injector.h), as OpenFOAM's patchInjection places its parcels.
//
// Reference: G. Turk, "Generating random points in triangles", Graphics Gems (1990): with
// uniforms u1, u2, the point (1 − √u1) a + √u1 (1 − u2) b + √u1 u2 c is uniform in the
// triangle abc. The triangle is chosen with probability ∝ its area (inverse of the cumulative
// areas), so the points are uniform over the whole patch.
// On a wedge (an axisymmetric mesh) the patch stands for the surface its centre-plane profile
// sweeps about the axis. A wedge face is planar and symmetric about the centre plane, so its
// width at a distance r from the axis is 2 r tan(θ/2): a point uniform on the face, moved along
// the hoop direction onto the centre plane, lands on the profile with density ∝ r, which is
// the swept surface's, and turned about the axis by a uniform angle it is uniform over that
// surface (of area π/tan(θ/2) times the face's). On a 2-D mesh the slab's faces are sampled as
// they are; the plane constraint (integrate/plane_constraint.h) then holds the particle on the
// mid-plane.
//
//     injectors { inlet { model patch; patchCoeffs { patch inlet; } count 1000; rate 1e5; } }
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/core/box.h"

#include <optional>
#include <vector>

namespace slides {

class PatchSampler {
public:
    /// The patch's faces as triangles, counter-clockwise seen from the gas
    /// (CarrierField::patchTriangles); at least one with a positive area. With an axisymmetric
    /// frame (CarrierField::axisymmetry), the faces are a wedge's and the surface is swept.
    explicit PatchSampler(std::vector<PatchTriangle> triangles,
                          std::optional<AxisymmetricFrame> sweep = std::nullopt);

    struct Point {
        Vec3 position; ///< on the patch, moved into the gas by 1e-9 of its triangle's size
        Vec3 normal;   ///< unit normal of the patch there, into the gas
        Mat3 turn = Mat3::Identity(); ///< the turn about a wedge's axis that took it there
        std::size_t triangle = 0;     ///< the index of the triangle it was drawn on
    };
    /// The point of uniforms on [0, 1): the first picks the triangle, the next two the point in
    /// it; on a wedge, uniformTurn the angle about the axis (ignored otherwise).
    Point draw(double uniformArea, double u1, double u2, double uniformTurn = 0) const;
    /// Whether the patch is swept about a wedge's axis (draw then needs uniformTurn).
    bool swept() const { return sweep_.has_value(); }
    /// Total area [m²], of the swept surface on a wedge.
    double area() const;
    /// A box holding every point draw returns: the faces' (with the hair into the gas and a
    /// margin for rounding), or on a wedge the box of the cylinder about the axis that holds
    /// the swept surface.
    const Box& bounds() const { return bounds_; }

private:
    std::vector<PatchTriangle> triangles_;
    std::vector<double> cumulativeArea_; ///< of triangles [0, k]
    std::optional<AxisymmetricFrame> sweep_;
    Box bounds_;
};

} // namespace slides
