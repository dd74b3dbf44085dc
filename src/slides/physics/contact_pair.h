// The effective properties of two bodies in contact: mass, radius, Young's and shear moduli,
// yield stress and work of adhesion, as the contact laws of Chapter 2 use them.
//
// Reference: Johnson, Contact Mechanics (1985), §4.2 and Mindlin (1949): 1/R* = 1/R₁ + 1/R₂,
// 1/m* = 1/m₁ + 1/m₂, 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂, 1/G* = (2 − ν₁)/G₁ + (2 − ν₂)/G₂
// (Eq. 2.4, 2.5, 2.7). A wall, or a particle already in the deposit, is a rigid body of
// infinite mass (and a plane of infinite radius). Elastic constants come from the bulk and
// shear moduli of Table 5.2: E = 9KG/(3K + G), ν = (3K − 2G)/(2(3K + G)).
//
//     particles { material { bulkModulus 167e9; shearModulus 77e9; yieldStress 200e6;
//                            surfaceEnergy 0.046; } }
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace slides {

/// Young's modulus and Poisson ratio of one material.
struct ElasticMaterial {
    double youngsModulus = 0; ///< E [Pa]; +∞ for a rigid wall
    double poissonRatio = 0;  ///< ν
    double shearModulus() const { return youngsModulus / (2.0 * (1.0 + poissonRatio)); }
};

/// A rigid wall: infinite moduli, so only the sphere deforms.
inline ElasticMaterial rigidMaterial() { return {std::numeric_limits<double>::infinity(), 0.0}; }

/// Elastic, plastic and surface properties of one material (SI units; 0 = not given).
struct MaterialSettings {
    double bulkModulus = 0;   ///< K [Pa]
    double shearModulus = 0;  ///< G [Pa]
    double yieldStress = 0;   ///< Y [Pa]
    double surfaceEnergy = 0; ///< γ [J/m²]
    bool operator==(const MaterialSettings&) const = default;

    bool elastic() const { return bulkModulus > 0 && shearModulus > 0; }
    ElasticMaterial elasticMaterial() const {
        const double k = bulkModulus, g = shearModulus;
        return {9 * k * g / (3 * k + g), (3 * k - 2 * g) / (2 * (3 * k + g))};
    }
};

/// One body in a contact: mass and radius (infinite for walls and the deposit), material.
struct ContactBody {
    double mass = std::numeric_limits<double>::infinity();   ///< [kg]
    double radius = std::numeric_limits<double>::infinity(); ///< [m]
    const MaterialSettings* material = nullptr;
};

/// The effective properties of a pair.
struct ContactPair {
    double radius = 0;         ///< R* [m]
    double mass = 0;           ///< m* [kg]
    double youngsModulus = 0;  ///< E* [Pa] (0 when a body gives no moduli)
    double shearModulus = 0;   ///< G* [Pa]
    double yieldStress = 0;    ///< the softer body's Y [Pa]; 0 = neither gives one
    double workOfAdhesion = 0; ///< W₁₂ = 2√(γ₁γ₂) [J/m²] (Berthelot rule; Eq. 2.74)
};

/// Mass of a sphere, (4/3)πR³ρ [kg].
inline double sphereMass(double radius, double density) {
    return 4.0 / 3.0 * M_PI * radius * radius * radius * density;
}

/// 1/(1/a + 1/b) with 1/∞ = 0.
inline double harmonicSum(double a, double b) { return 1.0 / (1.0 / a + 1.0 / b); }

/// Radius, mass and moduli of two elastic bodies (a rigid one: rigidMaterial(), infinite
/// radius and mass for a wall).
inline ContactPair elasticPair(const ElasticMaterial& a, double radiusA, double massA,
                               const ElasticMaterial& b, double radiusB, double massB) {
    // 1/E* and 1/G* contributions of one body: (1−ν²)/E and (2−ν)/G, 0 for a rigid body.
    const auto normalCompliance = [](const ElasticMaterial& m) {
        return (1 - m.poissonRatio * m.poissonRatio) / m.youngsModulus;
    };
    const auto shearCompliance = [](const ElasticMaterial& m) {
        return (2 - m.poissonRatio) / m.shearModulus();
    };
    ContactPair pair;
    pair.radius = harmonicSum(radiusA, radiusB);
    pair.mass = harmonicSum(massA, massB);
    pair.youngsModulus = 1.0 / (normalCompliance(a) + normalCompliance(b));
    pair.shearModulus = 1.0 / (shearCompliance(a) + shearCompliance(b));
    return pair;
}

/// A sphere against a wall (infinite radius and mass).
inline ContactPair sphereWallPair(const ElasticMaterial& sphere, double radius, double mass,
                                  const ElasticMaterial& wall) {
    constexpr double infinite = std::numeric_limits<double>::infinity();
    return elasticPair(sphere, radius, mass, wall, infinite, infinite);
}

/// The pair of two bodies of the scene: moduli when both materials give them, the softer
/// yield stress, the work of adhesion.
inline ContactPair contactPair(const ContactBody& a, const ContactBody& b) {
    const MaterialSettings& ma = *a.material;
    const MaterialSettings& mb = *b.material;
    ContactPair pair;
    if (ma.elastic() && mb.elastic())
        pair = elasticPair(ma.elasticMaterial(), a.radius, a.mass, mb.elasticMaterial(), b.radius,
                           b.mass);
    pair.radius = harmonicSum(a.radius, b.radius);
    pair.mass = harmonicSum(a.mass, b.mass);
    const double ya = ma.yieldStress > 0 ? ma.yieldStress : mb.yieldStress;
    const double yb = mb.yieldStress > 0 ? mb.yieldStress : ma.yieldStress;
    pair.yieldStress = std::min(ya, yb);
    pair.workOfAdhesion = 2 * std::sqrt(ma.surfaceEnergy * mb.surfaceEnergy);
    return pair;
}

} // namespace slides
