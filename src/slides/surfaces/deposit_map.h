// Deposit map: the height of the deposit over a target plane, on a square lattice of pixels
// in the plane (the thickness a profilometer would measure).
//
// Each stuck particle is a sphere of centre height h above the plane; over a pixel centre at
// in-plane distance r < R from its centre it reaches h + √(R² − r²). A pixel holds the
// highest of these (0 where no particle covers it). Pixels are a quarter of the mean stuck
// radius unless the deposit's extent would need more than maxPixels; the lattice covers the
// deposit plus one radius.
#pragma once

#include "slides/surfaces/arrival.h"
#include "slides/surfaces/surface_settings.h"

#include <vector>

namespace slides {

struct DepositMap {
    Vec3 origin = Vec3::Zero(); ///< centre of the first pixel, on the plane [m]
    Vec3 uAxis = Vec3::UnitX(), vAxis = Vec3::UnitY(), normal = Vec3::UnitZ(); ///< right-handed
    double pixel = 0;                                                          ///< pixel edge [m]
    int columns = 0, rows = 0;
    std::vector<double> height; ///< [m], columns fastest
};

/// The map of the particles stuck on surface (its arrivals); empty without any.
DepositMap depositMap(const Surface& plane, int surface, const std::vector<Arrival>& arrivals,
                      long maxPixels = 4'000'000);

} // namespace slides
