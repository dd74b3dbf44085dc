#include "slides/integrate/nearby_spheres.h"

#include <algorithm>
#include <cmath>

namespace slides {

void NearbySpheres::gather(const ParticleCloud& cloud, const Box& starts, double contact,
                           std::size_t placing) {
    // The box of the held start points: of the held corners of `starts` (a linear map's image
    // of a box is the hull of its corners' images).
    Box heldStarts{Vec3::Constant(INFINITY), Vec3::Constant(-INFINITY)};
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 point = held(Vec3(corner & 1 ? starts.max.x() : starts.min.x(),
                                     corner & 2 ? starts.max.y() : starts.min.y(),
                                     corner & 4 ? starts.max.z() : starts.min.z()));
        heldStarts.min = heldStarts.min.cwiseMin(point);
        heldStarts.max = heldStarts.max.cwiseMax(point);
    }
    const Box region{heldStarts.min.array() - contact, heldStarts.max.array() + contact};
    centres_.clear();
    radii_.clear();
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const Vec3 centre = held(cloud.position[i]);
        if (!insideBox(region, centre)) continue;
        centres_.push_back(centre);
        radii_.push_back(cloud.radius[i]);
    }
    // Cells of at least the contact distance (so an overlapping pair lies in neighbouring
    // cells), doubled until there are at most about two a sphere.
    const Vec3 extent = region.max - region.min;
    const double mostCells = 2.0 * static_cast<double>(centres_.size() + placing) + 27;
    const auto cellsOfEdge = [&](double edge) {
        return (extent / edge).array().floor().max(1.0).prod();
    };
    double edge = contact;
    while (cellsOfEdge(edge) > mostCells) edge *= 2;
    PackingRegion box;
    box.lower = region.min;
    box.upper = region.max;
    grid_.emplace(box, edge);
    for (std::size_t j = 0; j < centres_.size(); ++j)
        grid_->insert(static_cast<std::uint32_t>(j), centres_[j]);
}

bool NearbySpheres::overlaps(const Vec3& centre, double radius) const {
    const Vec3 at = held(centre);
    bool overlapping = false;
    grid_->forEachNear(at, [&](std::uint32_t j) {
        const double contact = radius + radii_[j];
        overlapping = overlapping || (at - centres_[j]).squaredNorm() < contact * contact;
    });
    return overlapping;
}

void NearbySpheres::add(const Vec3& centre, double radius) {
    const Vec3 at = held(centre);
    grid_->insert(static_cast<std::uint32_t>(centres_.size()), at);
    centres_.push_back(at);
    radii_.push_back(radius);
}

} // namespace slides
