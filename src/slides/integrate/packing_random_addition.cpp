#include "slides/integrate/packing_random_addition.h"

#include "slides/integrate/packing_grid.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace slides {

namespace {

/// Consecutive failed uniform attempts after which the attempts come from the voxels.
constexpr long uniformAttempts = 4096;
/// Halvings of the voxels' edge before the search gives up (stalled, not proven saturated).
constexpr int largestLevel = 30;
/// Voxels beyond which the search gives up (about 50 MB).
constexpr std::size_t voxelLimit = std::size_t(1) << 21;

Vec3 uniformIn(const Vec3& lower, const Vec3& size, RandomStream& random) {
    Vec3 point;
    for (int a = 0; a < 3; ++a) point[a] = lower[a] + size[a] * random.uniform();
    return point;
}

} // namespace

PackedEnsemble addRandomSequentially(const PackingRegion& region, std::span<const double> radii,
                                     RandomStream& random) {
    PackedEnsemble out;
    if (radii.empty()) {
        out.complete = true;
        return out;
    }
    const double largest = *std::max_element(radii.begin(), radii.end());
    const double smallest = *std::min_element(radii.begin(), radii.end());
    PackingGrid grid(region, 2 * largest);
    const Vec3 lower = region.boundsLower(), size = region.boundsUpper() - lower;

    const auto fits = [&](const Vec3& centre, double radius) {
        if (!region.holds(centre, radius)) return false;
        bool clear = true;
        grid.forEachNear(centre, [&](std::uint32_t j) {
            const double contact = radius + out.radii[j];
            clear = clear &&
                    region.separation(centre, out.centres[j]).squaredNorm() >= contact * contact;
        });
        return clear;
    };
    // A voxel is of no use once every point of it lies outside the centres' room or inside the
    // exclusion sphere of a placed sphere (for the smallest radius still to come).
    Vec3 edge = Vec3::Zero();
    const auto useless = [&](const Vec3& corner) {
        const Vec3 middle = corner + 0.5 * edge;
        if (region.depthInside(middle) < smallest - 0.5 * edge.norm()) return true;
        bool covered = false;
        grid.forEachNear(middle, [&](std::uint32_t j) {
            const Vec3 farthest = region.separation(middle, out.centres[j]).cwiseAbs() + 0.5 * edge;
            const double exclusion = out.radii[j] + smallest;
            covered = covered || farthest.squaredNorm() < exclusion * exclusion;
        });
        return covered;
    };
    std::vector<Vec3> voxels, finer;
    bool fromVoxels = false;
    int level = 0;
    long failures = 0, roundAttempts = 0;
    std::size_t placed = 0;
    while (placed < radii.size()) {
        Vec3 centre;
        if (fromVoxels) {
            if (voxels.empty()) {
                out.saturated = true;
                break;
            }
            const auto pick = std::min(voxels.size() - 1,
                                       static_cast<std::size_t>(random.uniform() * voxels.size()));
            centre = uniformIn(voxels[pick], edge, random);
        } else {
            centre = uniformIn(lower, size, random);
        }
        ++out.attempts;
        if (fits(centre, radii[placed])) {
            grid.insert(static_cast<std::uint32_t>(placed), centre);
            out.centres.push_back(centre);
            out.radii.push_back(radii[placed]);
            ++placed;
            failures = 0;
        } else {
            ++failures;
        }
        if (!fromVoxels && failures >= uniformAttempts) {
            // Voxels of edge about half the smallest radius over the bounding box.
            fromVoxels = true;
            std::array<long, 3> count{};
            for (int a = 0; a < 3; ++a) {
                count[a] = std::max(1L, static_cast<long>(std::ceil(size[a] / (0.5 * smallest))));
                edge[a] = size[a] / static_cast<double>(count[a]);
            }
            for (long i = 0; i < count[0]; ++i)
                for (long j = 0; j < count[1]; ++j)
                    for (long k = 0; k < count[2]; ++k) {
                        const Vec3 corner = lower + Vec3(static_cast<double>(i) * edge[0],
                                                         static_cast<double>(j) * edge[1],
                                                         static_cast<double>(k) * edge[2]);
                        if (!useless(corner)) voxels.push_back(corner);
                    }
        } else if (fromVoxels && ++roundAttempts >= static_cast<long>(voxels.size())) {
            // Voxels that multiply instead of thinning out hold room only for the smaller
            // spheres (unequal radii): the search has stalled, not saturated.
            if (level == largestLevel || voxels.size() > voxelLimit) break;
            ++level;
            roundAttempts = 0;
            edge *= 0.5;
            finer.clear();
            for (const Vec3& voxel : voxels)
                for (int child = 0; child < 8; ++child) {
                    const Vec3 corner =
                        voxel + Vec3((child & 1) * edge[0], (child >> 1 & 1) * edge[1],
                                     (child >> 2 & 1) * edge[2]);
                    if (!useless(corner)) finer.push_back(corner);
                }
            voxels.swap(finer);
        }
    }
    out.complete = placed == radii.size();
    return out;
}

} // namespace slides
