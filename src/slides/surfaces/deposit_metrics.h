// Deposit metrics of Eq. 5.12: the deposit height h_dep and the deposited fraction n_dep of
// one target surface.
//
// Reference: Eq. 5.12 of the reference, h_dep = (x_max + R_av) − (x_min − R_av),
// n_dep = N_stuck / N_p, with x the height of a stuck particle's centre above the target
// plane (along its normal), R_av the stuck particles' mean radius and N_p the particles
// injected.
#pragma once

#include "slides/surfaces/arrival.h"
#include "slides/surfaces/surface_settings.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace slides {

struct DepositMetrics {
    long stuck = 0;           ///< N_stuck
    double fraction = 0;      ///< n_dep
    double height = 0;        ///< h_dep [m] (0 without a deposit)
    double meanRadius = 0;    ///< R_av [m]
    double lowestCentre = 0;  ///< x_min [m]
    double highestCentre = 0; ///< x_max [m]
};

/// Eq. 5.12 for the particles stuck on surface (the arrivals there, for a deposit surface).
inline DepositMetrics depositMetrics(const Surface& plane, int surface,
                                     const std::vector<Arrival>& arrivals, long injected) {
    DepositMetrics metrics;
    double radiusSum = 0;
    double lowest = std::numeric_limits<double>::infinity();
    double highest = -lowest;
    for (const Arrival& arrival : arrivals) {
        if (arrival.surface != surface) continue;
        const double height = (arrival.position - plane.point).dot(plane.normal);
        lowest = std::min(lowest, height);
        highest = std::max(highest, height);
        radiusSum += arrival.radius;
        ++metrics.stuck;
    }
    if (injected > 0) metrics.fraction = static_cast<double>(metrics.stuck) / injected;
    if (metrics.stuck == 0) return metrics;
    metrics.meanRadius = radiusSum / static_cast<double>(metrics.stuck);
    metrics.lowestCentre = lowest;
    metrics.highestCentre = highest;
    metrics.height = (highest + metrics.meanRadius) - (lowest - metrics.meanRadius);
    return metrics;
}

} // namespace slides
