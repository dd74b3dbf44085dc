// Carrier settings: the gas (`fluid {}`) and the field that carries the particles (`carrier {}`),
// with the name tables of the carrier types, jet profiles and turbulence scalings.
//
//     fluid   { density 1.2; kinematicViscosity 1.5e-5; temperature 293; }
//     carrier { type analyticJet; analyticJetCoeffs { profile axisymmetric; nozzleVelocity 50; }
//               turbulence { scaling jetLocal; intensity 0.1; lengthScaleToHalfWidth 0.2; } }
//
// How to add a carrier type: an enumerator, its name in carrierTypeNames(), its key rows in
// config/scene_keys.cpp and its construction in carrier/make_carrier.cpp.
#pragma once

#include "slides/carrier/foam_interpolation.h"
#include "slides/carrier/foam_series.h"
#include "slides/carrier/jet_frame.h"
#include "slides/carrier/jet_scalars.h"
#include "slides/carrier/pulsed_jet.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace slides {

struct FluidSettings {
    double density = 0;             ///< ρf [kg/m³]
    double kinematicViscosity = 0;  ///< ν [m²/s]
    double temperature = 0;         ///< [K]
    double thermalConductivity = 0; ///< K_f [W/(m K)], heat transfer
    double specificHeat = 0;        ///< c_f [J/(kg K)], heat transfer
};

enum class CarrierType {
    analyticJet,
    roundLaminarJet,
    foamField,
    none,
    oscillatingGas,
    taylorGreenVortex,
    planePoiseuille
};

struct CarrierTypeName {
    CarrierType value;
    std::string_view name;
};

constexpr std::array<CarrierTypeName, 7> carrierTypeNames() {
    return {{{CarrierType::analyticJet, "analyticJet"},
             {CarrierType::roundLaminarJet, "roundLaminarJet"},
             {CarrierType::foamField, "foamField"},
             {CarrierType::none, "none"},
             {CarrierType::oscillatingGas, "oscillatingGas"},
             {CarrierType::taylorGreenVortex, "taylorGreenVortex"},
             {CarrierType::planePoiseuille, "planePoiseuille"}}};
}

/// Whether a carrier type gives ∇²U (the Faxén terms, physics/faxen.h): the closed-form fields
/// with curvature; a mesh's cellPoint field is linear in each tetrahedron.
constexpr bool givesVelocityLaplacian(CarrierType type) {
    return type == CarrierType::planePoiseuille || type == CarrierType::taylorGreenVortex ||
           type == CarrierType::oscillatingGas;
}

struct JetGeometryName {
    JetGeometry value;
    std::string_view name;
};

constexpr std::array<JetGeometryName, 2> jetGeometryNames() {
    return {{{JetGeometry::planar, "planar"}, {JetGeometry::axisymmetric, "axisymmetric"}}};
}

struct TurbulenceScalingName {
    TurbulenceScaling value;
    std::string_view name;
};

constexpr std::array<TurbulenceScalingName, 2> turbulenceScalingNames() {
    return {{{TurbulenceScaling::uniform, "uniform"}, {TurbulenceScaling::jetLocal, "jetLocal"}}};
}

struct CarrierSettings {
    CarrierType type = CarrierType::analyticJet;
    JetGeometry profile = JetGeometry::axisymmetric; ///< analyticJet only
    double nozzleVelocity = 0;                       ///< U0 [m/s]
    double coreLength = 0;                           ///< unentrained core [m]
    double viscosity = 0; ///< ν that sets the spreading: effectiveViscosity or the fluid's
    std::optional<double> C1, C2, C3;        ///< Eq. 5.10/5.11 coefficients when given explicitly
    std::optional<JetTurbulence> turbulence; ///< k, ε of the analytic jets (none: laminar)
    /// A pulsed nozzle of the analytic jets (carrier/pulsed_jet.h); none (or amplitude 0): steady
    std::optional<JetPulsation> pulsation;
    // foamField only:
    std::string foamTime = "latestTime"; ///< time directory: latestTime or a time value
    FoamInterpolation interpolation = FoamInterpolation::cellPoint;
    double latticeSpacing = 0; ///< interpolation lattice: node spacing [m], 0: extent/100
    std::optional<FoamSeriesSettings> foamSeries; ///< times (and cycle): a time series
    // oscillatingGas only (carrier/oscillating_gas.h):
    Vec3 oscillationAmplitude = Vec3::Zero(); ///< U of u = U sin 2πft [m/s]
    double oscillationFrequency = 0;          ///< f [Hz]
    // taylorGreenVortex only (carrier/taylor_green_vortex.h):
    double vortexVelocity = 0;   ///< U [m/s]
    double vortexWavelength = 0; ///< L = 2π/k [m]
    // planePoiseuille only (carrier/plane_poiseuille.h):
    double centrelineVelocity = 0; ///< U [m/s]
    double channelHalfWidth = 0;   ///< h [m]
};

} // namespace slides
