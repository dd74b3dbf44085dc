// Injection settings: the particles (`particles {}`) and how they enter (`injection {}`), with
// the name tables of the radius distributions and injection modes.
//
//     particles { count 8000; density 2500;
//                 radiusDistribution { type logNormal; median 5e-6; geometricStandardDeviation 1.5;
//                                      minimum 1e-6; maximum 2e-5; } }
//     injection { mode rate; rate 8e4; crossSpanSpeed 0.5; seed 1; }
//               // or: mode lattice; latticeCoeffs { origin (0 0 0); spacing 1e-4;
//               //                                   sites (10 10 10); velocitySpread 0.1; }
//
// How to add a mode or distribution: an enumerator, its name in its table below, its key rows
// in config/scene_keys.cpp and its case in integrate/injector.cpp.
#pragma once

#include "slides/core/vector.h"
#include "slides/physics/contact_pair.h"

#include <array>
#include <cstdint>
#include <string_view>

namespace slides {

enum class RadiusDistributionKind { fixed, normal, logNormal };

struct RadiusDistributionName {
    RadiusDistributionKind value;
    std::string_view name;
};

constexpr std::array<RadiusDistributionName, 3> radiusDistributionNames() {
    return {{{RadiusDistributionKind::fixed, "fixed"},
             {RadiusDistributionKind::normal, "normal"},
             {RadiusDistributionKind::logNormal, "logNormal"}}};
}

struct RadiusDistribution {
    RadiusDistributionKind kind = RadiusDistributionKind::fixed;
    double value = 0;                      ///< fixed radius [m]
    double mean = 0;                       ///< normal: mean radius [m]
    double standardDeviation = 0;          ///< normal [m]
    double median = 0;                     ///< logNormal: median radius [m]
    double geometricStandardDeviation = 1; ///< logNormal: e^σ of ln R (≥ 1)
    double minimum = 0;                    ///< draws below are redrawn [m]
    double maximum = 0;                    ///< draws above are redrawn [m]
    /// Expected value of the (untruncated) distribution [m]: the one "mean radius" of a run
    /// (its Stokes time, the scene analysis, the summary).
    double meanRadius() const;
};

struct ParticleSettings {
    long count = 0;
    double density = 0; ///< ρp [kg/m³]
    RadiusDistribution radius;
    MaterialSettings material;
    double specificHeat = 0;         ///< c_p [J/(kg K)], heat transfer
    double thermalConductivity = 0;  ///< K_p [W/(m K)], for the Biot number; 0: not given
    double injectionTemperature = 0; ///< θ at injection [K], heat transfer
};

enum class InjectionMode { rate, allAtStart, lattice };

struct InjectionModeName {
    InjectionMode value;
    std::string_view name;
};

constexpr std::array<InjectionModeName, 3> injectionModeNames() {
    return {{{InjectionMode::rate, "rate"},
             {InjectionMode::allAtStart, "allAtStart"},
             {InjectionMode::lattice, "lattice"}}};
}

struct InjectionSettings {
    InjectionMode mode = InjectionMode::rate;
    double rate = 0;           ///< particles per second (mode rate)
    double crossSpanSpeed = 0; ///< magnitude of the random velocity ⟂ axis [m/s]
    std::uint64_t seed = 1;
    // Mode lattice: a simple cubic lattice of sites, filled in order x, y, z.
    Vec3 latticeOrigin = Vec3::Zero(); ///< lower corner of the first cell [m]
    double latticeSpacing = 0;         ///< a [m]
    std::array<int, 3> latticeSites{}; ///< per axis
    double latticeVelocitySpread = 0;  ///< uniform in [−spread, spread] per component [m/s]
};

} // namespace slides
