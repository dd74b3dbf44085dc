// Deposit: the particles that stuck to a deposition surface, a static bed of spheres that
// incoming particles collide with and may stick to (Section 5.3.4 and Fig. 5.12 of the
// reference).
//
// A stuck particle leaves the moving cloud for good (Section 5.3.4: "removed from the set of
// dynamic particles ... remains adhered permanently"). Queries use a hashed cell grid
// (collide/cell_grid.h), rebuilt by index() when particles were added.
#pragma once

#include "slides/collide/cell_grid.h"
#include "slides/core/vector.h"

#include <cstdint>

#include <optional>
#include <vector>

namespace slides {

/// A moving sphere's first touch of a deposited particle during a step.
struct DepositTouch {
    std::size_t particle = 0; ///< index into the deposit
    double fraction = 0;      ///< of the step's chord
};

class Deposit {
public:
    /// species: the particle's (integrate/injection_settings.h), 0 when the particles are alike.
    void add(const Vec3& position, double radius, int surface, std::int32_t species = 0);
    /// Makes the particles added since the last call visible to firstTouch.
    void index();

    /// The first deposited particle that a sphere of the given radius touches while its
    /// centre moves from start to end, if any (collide/swept_contact.h).
    std::optional<DepositTouch> firstTouch(const Vec3& start, const Vec3& end, double radius) const;

    std::size_t size() const { return position_.size(); }
    const Vec3& position(std::size_t k) const { return position_[k]; }
    double radius(std::size_t k) const { return radius_[k]; }
    int surface(std::size_t k) const { return surface_[k]; } ///< the target it grew on
    std::int32_t species(std::size_t k) const { return species_[k]; }

private:
    std::vector<Vec3> position_;
    std::vector<double> radius_;
    std::vector<int> surface_;
    std::vector<std::int32_t> species_;
    CellGrid grid_;
    std::size_t indexed_ = 0; ///< particles the grid holds
    double largestRadius_ = 0;
    Vec3 lower_ = Vec3::Constant(INFINITY), upper_ = Vec3::Constant(-INFINITY); ///< centres' box
};

} // namespace slides
