// NearbySpheres: the spheres near an injector while it places a batch (integrate/injector.h) —
// the particles in flight inside a box about its start points, then each new one as it is
// placed — binned so that testing a start for overlap reads only the cells around it.
//
// Reference: the binning of Algorithm 4 (Eq. 4.36), through integrate/packing_grid.h, whose
// cells take a sphere at any time in O(1). Gathering is O(N) in the cloud; each test is O(1)
// however many particles crowd the injector, where comparing with every one near it would make a
// batch O(n·N_near) (quadratic for a dense patch or all at the start). The cells are at least
// the largest contact distance, coarsened until there are no more than about two a sphere, so
// memory stays O(N) however large the box. On a 2-D carrier every sphere is compared where the
// stepper will hold it, on the mid-plane (integrate/plane_constraint.h).
//
//     (no key: on for disc, cone and patch injectors when collisions are on)
#pragma once

#include "slides/core/box.h"
#include "slides/core/particle_cloud.h"
#include "slides/integrate/packing_grid.h"
#include "slides/integrate/plane_constraint.h"

#include <optional>
#include <vector>

namespace slides {

class NearbySpheres {
public:
    /// plane: a 2-D carrier's (planeConstraintOf), none for a 3-D one.
    explicit NearbySpheres(std::optional<PlaneConstraint> plane) : plane_(std::move(plane)) {}

    /// Forgets the last batch and gathers the particles of cloud whose centres lie within
    /// `contact` [m] (the largest sum of two radii, > 0) of `starts` (a box holding every start
    /// point), for a batch of `placing` new spheres.
    void gather(const ParticleCloud& cloud, const Box& starts, double contact, std::size_t placing);

    /// Whether a sphere of the radius at centre overlaps one gathered or added.
    bool overlaps(const Vec3& centre, double radius) const;

    /// Adds a sphere placed in the batch.
    void add(const Vec3& centre, double radius);

private:
    /// The point where the sphere at centre is compared: where the stepper holds it.
    Vec3 held(const Vec3& centre) const { return plane_ ? plane_->onMidPlane(centre) : centre; }

    std::optional<PlaneConstraint> plane_;
    std::vector<Vec3> centres_; ///< held
    std::vector<double> radii_;
    std::optional<PackingGrid> grid_;
};

} // namespace slides
