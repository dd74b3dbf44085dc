// Erosion settings: the porous layer that a surface of interaction erode is (Section 5.2): its
// thickness d and width w (Fig. 5.1), porosity and bounds weight (Eq. 5.1–5.3), the damage
// threshold σ₀ (Eq. 5.5–5.6) and the grid its stresses are evaluated on.
//
//     surfaces { target { type plane; point (0 0 0); normal (0 0 1); interaction erode;
//                         material { bulkModulus 100e9; shearModulus 46.15e9; }
//                         erosion { thickness 2e-3; width 8e-3; porosity 0.2; boundWeight 0.5;
//                                   threshold 1.2e9; cells (32 32 8); } } }
#pragma once

#include <array>

namespace slides {

struct ErosionSettings {
    double thickness = 0;     ///< d [m]
    double width = 0;         ///< w [m], the square layer's side, centred on the plane's point
    double porosity = 0;      ///< p, the pores' volume fraction (Eq. 5.3: v₁ = p)
    double boundWeight = 0.5; ///< φ of Eq. 5.3
    double threshold = 0;     ///< σ₀ [Pa] (Eq. 5.5–5.6)
    /// Across the width (two directions, even: a grid line on the centre), the thickness.
    std::array<int, 3> cells{};
};

} // namespace slides
