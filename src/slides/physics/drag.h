// Drag on a sphere: the correction f(Re) = Cd·Re/24 to Stokes drag, one entry per drag law.
//
// Reference: Eq. 3.16–3.17 of the reference (Haider & Levenspiel 1989, Powder Technol. 58:63,
// sphericity 1); Schiller & Naumann (1933) for comparison; Putnam (1961), the law of OpenFOAM's
// `sphereDrag` (SphereDragForce::CdRe), for comparisons with OpenFOAM's trackers; Stokes (1851).
// With f, the drag acceleration is (u − v)·f/τ_St, τ_St = ρp d²/(18 μ) (Eq. 3.16 divided by the
// particle mass).
//
//     physics { drag haiderLevenspiel; }   // stokes | schillerNaumann | haiderLevenspiel | putnam
//
// How to add a drag law: add an enumerator, its name to dragModelNames(), and its case to
// dragCorrection(); the family test (tests/unit/test_drag.cpp) then checks it automatically.
#pragma once

#include "slides/physics/particle_reynolds.h"

#include <array>
#include <cmath>
#include <string_view>

namespace slides {

enum class DragModel { stokes, schillerNaumann, haiderLevenspiel, putnam };

struct DragModelName {
    DragModel value;
    std::string_view name;
};

/// The name table of the drag family, as written in the dictionary.
constexpr std::array<DragModelName, 4> dragModelNames() {
    return {{{DragModel::stokes, "stokes"},
             {DragModel::schillerNaumann, "schillerNaumann"},
             {DragModel::haiderLevenspiel, "haiderLevenspiel"},
             {DragModel::putnam, "putnam"}}};
}

/// Cd·Re/24 for the given law; 1 for Stokes drag, → 1 as Re → 0 for every law.
inline double dragCorrection(DragModel model, double reynolds) {
    switch (model) {
    case DragModel::stokes: return 1.0;
    case DragModel::schillerNaumann:
        // Cd = 24/Re (1 + 0.15 Re^0.687) for Re < 1000, Cd = 0.44 above.
        return reynolds < 1000.0 ? 1.0 + 0.15 * std::pow(reynolds, 0.687) : 0.44 * reynolds / 24.0;
    case DragModel::haiderLevenspiel:
        // Eq. 3.17: Cd = 24/Re (1 + 0.1806 Re^0.6459) + 0.4251 / (1 + 6880.95/Re).
        return 1.0 + 0.1806 * std::pow(reynolds, 0.6459) +
               reynolds * 0.4251 / (24.0 * (1.0 + 6880.95 / reynolds));
    case DragModel::putnam:
        // OpenFOAM sphereDrag: Cd·Re = 24 (1 + Re^(2/3)/6) for Re ≤ 1000, 0.424 Re above.
        return reynolds > 1000.0 ? 0.424 * reynolds / 24.0
                                 : 1.0 + std::cbrt(reynolds * reynolds) / 6.0;
    }
    return 1.0;
}

/// Drag coefficient Cd(Re) = 24 f(Re) / Re.
inline double dragCoefficient(DragModel model, double reynolds) {
    return 24.0 * dragCorrection(model, reynolds) / reynolds;
}

/// Stokes response time τ_St = 2 ρp R² / (9 ρf ν) [s].
inline double stokesResponseTime(double particleDensity, double particleRadius, double fluidDensity,
                                 double kinematicViscosity) {
    return 2.0 * particleDensity * particleRadius * particleRadius /
           (9.0 * fluidDensity * kinematicViscosity);
}

/// What the drag response time of a particle depends on besides its radius and slip.
struct DragParameters {
    DragModel model = DragModel::haiderLevenspiel;
    double fluidDensity = 0;       ///< [kg/m³]
    double kinematicViscosity = 0; ///< [m²/s]
    double particleDensity = 0;    ///< [kg/m³]
    /// The same drag on a particle of density ρp (particle species,
    /// integrate/injection_settings.h).
    DragParameters withDensity(double density) const {
        DragParameters own = *this;
        own.particleDensity = density;
        return own;
    }
};

/// Drag response time τ = τ_St / f(Re) [s]: dv/dt = (u − v)/τ is Eq. 3.16's drag per unit mass.
inline double dragResponseTime(const DragParameters& drag, double particleRadius,
                               double slipSpeed) {
    const double reynolds = particleReynolds(slipSpeed, particleRadius, drag.kinematicViscosity);
    return stokesResponseTime(drag.particleDensity, particleRadius, drag.fluidDensity,
                              drag.kinematicViscosity) /
           dragCorrection(drag.model, reynolds);
}

} // namespace slides
