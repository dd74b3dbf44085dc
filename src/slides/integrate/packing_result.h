// PackedEnsemble: what a packing algorithm (integrate/packing_random_addition.h,
// packing_growth.h) returns: the spheres it placed, in the order of the radii it was given.
//
// Reference: Section 4.3.
#pragma once

#include "slides/core/vector.h"

#include <vector>

namespace slides {

struct PackedEnsemble {
    std::vector<Vec3> centres; ///< [m]
    std::vector<double> radii; ///< [m]; the first centres.size() of those asked for
    bool complete = false;     ///< every sphere asked for is placed at its full radius
    bool saturated = false;    ///< random addition: no space is left for another sphere
    long attempts = 0;         ///< random addition: insertion attempts, all spheres
    long sweeps = 0;           ///< growth: overlap-removal sweeps, all steps

    /// Σ (4/3) π r³ / regionVolume.
    double volumeFraction(double regionVolume) const;
};

} // namespace slides
