// PatchWall: a wall patch of the OpenFOAM mesh as a surface that spheres meet (type patch).
//
// The patch's faces, fanned into triangles about their point averages (as the mesh's
// tetrahedra split them), are sorted into size classes (the distance from centroid to farthest
// vertex within a factor 2) and binned by centroid in one cell grid a class
// (collide/cell_grid.h), so that a graded mesh's fine faces are not searched with the reach of
// its coarse ones.
//
// A sphere of radius R moving on the chord x₀ → x₁ touches triangle k (unit normal n into the
// gas, a vertex a) where its centre's gap d = (x − a)·n − R falls to 0, at α = d₀/(d₀ − d₁) as
// on a plane (surfaces/plane_contact.h), provided the centre then lies over the triangle (its
// projection inside it). A concave corner is met on either face; the sphere's contact with a
// convex edge or vertex itself is not sought, so there a sphere may pass within R of the edge.
// A centre already behind a face's plane does not meet that face.
//
//     surfaces { plate { type patch; patch plate; interaction deposit; material { ... } } }
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/collide/cell_grid.h"
#include "slides/surfaces/surface_settings.h"

#include <filesystem>
#include <optional>
#include <vector>

namespace slides {

/// Where a sphere meets a patch: the fraction of the chord, the face's plane there.
struct PatchTouch {
    double fraction = 0;
    Vec3 normal = Vec3::UnitX(); ///< unit, into the gas
    Vec3 point = Vec3::Zero();   ///< a point of the face's plane
};

class PatchWall {
public:
    explicit PatchWall(const std::vector<PatchTriangle>& triangles);

    /// The first touch along start → end of a sphere of the given radius that accept(fraction,
    /// normal) takes (the caller's test that the sphere approaches the face there).
    template <typename Accept>
    std::optional<PatchTouch> firstTouch(const Vec3& start, const Vec3& end, double radius,
                                         Accept accept) const {
        const Vec3 centre = 0.5 * (start + end);
        std::optional<PatchTouch> first;
        for (const SizeClass& size : classes_) {
            const double reach = 0.5 * (end - start).norm() + radius + size.reach;
            if (((centre.array() + reach) < size.lower.array()).any() ||
                ((centre.array() - reach) > size.upper.array()).any())
                continue;
            size.grid.forEachPointWithin(centre, reach, [&](std::uint32_t j) {
                const std::uint32_t k = size.triangles[j];
                const auto fraction = touchFraction(k, start, end, radius);
                if (fraction && (!first || *fraction < first->fraction) &&
                    accept(*fraction, normal_[k]))
                    first = PatchTouch{*fraction, normal_[k], vertex_[k]};
            });
        }
        return first;
    }

    /// The area-weighted centroid and mean unit normal (into the gas) of the patch.
    const Vec3& centroid() const { return centroid_; }
    const Vec3& meanNormal() const { return meanNormal_; }
    std::size_t size() const { return normal_.size(); }

private:
    std::optional<double> touchFraction(std::size_t k, const Vec3& start, const Vec3& end,
                                        double radius) const;

    /// Triangles whose centroid-to-vertex distances lie within a factor 2, binned by centroid.
    struct SizeClass {
        double reach = 0;                     ///< the largest centroid-to-vertex distance
        std::vector<std::uint32_t> triangles; ///< indices, in the order of the grid's points
        Vec3 lower, upper;                    ///< the box of their vertices
        CellGrid grid;
    };

    std::vector<Vec3> vertex_, edgeB_, edgeC_; ///< a, b − a, c − a of each triangle
    std::vector<Vec3> normal_;                 ///< unit, into the gas
    Vec3 centroid_ = Vec3::Zero(), meanNormal_ = Vec3::UnitX();
    std::vector<SizeClass> classes_;
};

/// The surfaces with each patch surface's point and normal set to its patch's mean plane (for
/// the deposit's metrics and map). InputError in dictionaryFile at surfaces.NAME.patch for a
/// deposit patch without a mean direction (a closed one, whose face normals cancel).
std::vector<Surface> placePatchSurfaces(std::vector<Surface> surfaces, const CarrierField& carrier,
                                        const std::filesystem::path& dictionaryFile);

} // namespace slides
