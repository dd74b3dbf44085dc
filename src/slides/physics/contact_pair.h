// The effective properties of two bodies in contact: mass, radius, modulus, yield stress and
// work of adhesion, as the contact laws of Chapter 2 use them.
//
// Reference: Johnson, Contact Mechanics (1985), §4.2: 1/R* = 1/R₁ + 1/R₂,
// 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂, 1/m* = 1/m₁ + 1/m₂. A wall, or a particle already in
// the deposit, is a rigid body of infinite mass (and a plane of infinite radius). Elastic
// constants come from the bulk and shear moduli of Table 5.2: E = 9KG/(3K + G),
// ν = (3K − 2G)/(2(3K + G)).
//
//     particles { material { bulkModulus 167e9; shearModulus 77e9; yieldStress 200e6;
//                            surfaceEnergy 0.046; } }
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace slides {

/// Elastic, plastic and surface properties of one material (SI units; 0 = not given).
struct MaterialSettings {
    double bulkModulus = 0;   ///< K [Pa]
    double shearModulus = 0;  ///< G [Pa]
    double yieldStress = 0;   ///< Y [Pa]
    double surfaceEnergy = 0; ///< γ [J/m²]

    double youngsModulus() const {
        return 9 * bulkModulus * shearModulus / (3 * bulkModulus + shearModulus);
    }
    double poissonRatio() const {
        return (3 * bulkModulus - 2 * shearModulus) / (2 * (3 * bulkModulus + shearModulus));
    }
    bool elastic() const { return bulkModulus > 0 && shearModulus > 0; }
};

/// One body in a contact: mass and radius (infinite for walls and the deposit), material.
struct ContactBody {
    double mass = std::numeric_limits<double>::infinity();   ///< [kg]
    double radius = std::numeric_limits<double>::infinity(); ///< [m]
    const MaterialSettings* material = nullptr;
};

/// The effective properties of a pair.
struct ContactPair {
    double mass = 0;           ///< m* [kg]
    double radius = 0;         ///< R* [m]
    double modulus = 0;        ///< E* [Pa]
    double yieldStress = 0;    ///< the softer body's Y [Pa]; 0 = neither gives one
    double workOfAdhesion = 0; ///< W₁₂ = 2√(γ₁γ₂) [J/m²] (Berthelot rule; Eq. 2.74)
};

/// 1/(1/a + 1/b) with 1/∞ = 0.
inline double harmonicSum(double a, double b) { return 1.0 / (1.0 / a + 1.0 / b); }

inline ContactPair contactPair(const ContactBody& a, const ContactBody& b) {
    ContactPair pair;
    pair.mass = harmonicSum(a.mass, b.mass);
    pair.radius = harmonicSum(a.radius, b.radius);
    const MaterialSettings& ma = *a.material;
    const MaterialSettings& mb = *b.material;
    const auto compliance = [](const MaterialSettings& m) {
        const double nu = m.poissonRatio();
        return (1 - nu * nu) / m.youngsModulus();
    };
    if (ma.elastic() && mb.elastic()) pair.modulus = 1.0 / (compliance(ma) + compliance(mb));
    const double ya = ma.yieldStress > 0 ? ma.yieldStress : mb.yieldStress;
    const double yb = mb.yieldStress > 0 ? mb.yieldStress : ma.yieldStress;
    pair.yieldStress = std::min(ya, yb);
    pair.workOfAdhesion = 2 * std::sqrt(ma.surfaceEnergy * mb.surfaceEnergy);
    return pair;
}

} // namespace slides
