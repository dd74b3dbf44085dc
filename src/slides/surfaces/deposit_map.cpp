#include "slides/surfaces/deposit_map.h"

#include <algorithm>
#include <cmath>

namespace slides {

namespace {

/// A unit vector in the plane of normal n: n crossed with the axis least aligned with it.
Vec3 inPlaneAxis(const Vec3& normal) {
    Vec3::Index axis = 0;
    normal.cwiseAbs().minCoeff(&axis);
    return Vec3::Unit(axis).cross(normal).normalized();
}

} // namespace

DepositMap depositMap(const Surface& plane, int surface, const std::vector<Arrival>& arrivals,
                      long maxPixels) {
    DepositMap map;
    map.normal = plane.normal;
    map.uAxis = inPlaneAxis(plane.normal);
    map.vAxis = map.normal.cross(map.uAxis);
    struct Cap {
        double u, v, height, radius;
    };
    std::vector<Cap> caps;
    double uMin = INFINITY, uMax = -INFINITY, vMin = INFINITY, vMax = -INFINITY, radiusSum = 0;
    for (const Arrival& arrival : arrivals) {
        if (arrival.surface != surface) continue;
        const Vec3 offset = arrival.position - plane.point;
        const Cap cap{offset.dot(map.uAxis), offset.dot(map.vAxis), offset.dot(map.normal),
                      arrival.radius};
        uMin = std::min(uMin, cap.u - cap.radius);
        uMax = std::max(uMax, cap.u + cap.radius);
        vMin = std::min(vMin, cap.v - cap.radius);
        vMax = std::max(vMax, cap.v + cap.radius);
        radiusSum += cap.radius;
        caps.push_back(cap);
    }
    if (caps.empty()) return map;
    map.pixel = 0.25 * radiusSum / static_cast<double>(caps.size());
    const double area = (uMax - uMin) * (vMax - vMin);
    map.pixel = std::max(map.pixel, std::sqrt(area / static_cast<double>(maxPixels)));
    map.columns = static_cast<int>(std::ceil((uMax - uMin) / map.pixel)) + 1;
    map.rows = static_cast<int>(std::ceil((vMax - vMin) / map.pixel)) + 1;
    map.origin = plane.point + uMin * map.uAxis + vMin * map.vAxis;
    map.height.assign(static_cast<std::size_t>(map.columns) * map.rows, 0.0);
    for (const Cap& cap : caps) {
        const int c0 =
            std::max(0, static_cast<int>(std::floor((cap.u - cap.radius - uMin) / map.pixel)));
        const int c1 = std::min(
            map.columns - 1, static_cast<int>(std::ceil((cap.u + cap.radius - uMin) / map.pixel)));
        const int r0 =
            std::max(0, static_cast<int>(std::floor((cap.v - cap.radius - vMin) / map.pixel)));
        const int r1 = std::min(
            map.rows - 1, static_cast<int>(std::ceil((cap.v + cap.radius - vMin) / map.pixel)));
        for (int r = r0; r <= r1; ++r)
            for (int c = c0; c <= c1; ++c) {
                const double du = uMin + c * map.pixel - cap.u, dv = vMin + r * map.pixel - cap.v;
                const double inside = cap.radius * cap.radius - du * du - dv * dv;
                if (inside < 0) continue;
                double& h = map.height[static_cast<std::size_t>(r) * map.columns + c];
                h = std::max(h, cap.height + std::sqrt(inside));
            }
    }
    return map;
}

} // namespace slides
