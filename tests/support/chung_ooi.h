// The materials of Chung & Ooi (2011), "Benchmark tests for verifying discrete element modelling
// codes at particle impact level", Granular Matter 13:643–656 (Tables 1–4), and their head-on
// impact scenes: two spheres, or a sphere on a rigid wall (test support for
// tests/support/dem_impact.h).
#pragma once

#include "dem_impact.h"

#include <algorithm>
#include <numbers>

namespace slides::test {

// Materials of Chung & Ooi (2011), Tables 1–4: E [Pa], ν, ρ [kg/m³].
struct BenchmarkMaterial {
    const char* name;
    double youngsModulus, poissonRatio, density;
    ElasticMaterial elastic() const { return {youngsModulus, poissonRatio}; }
};
constexpr BenchmarkMaterial glass{"glass", 4.8e10, 0.20, 2800};
constexpr BenchmarkMaterial limestone{"limestone", 2.0e10, 0.25, 2500};
constexpr BenchmarkMaterial aluminiumAlloy{"aluminiumAlloy", 7.0e10, 0.33, 2700};
constexpr BenchmarkMaterial magnesiumAlloy{"magnesiumAlloy", 4.0e10, 0.35, 1800};
constexpr BenchmarkMaterial aluminiumOxide{"aluminiumOxide", 3.8e11, 0.23, 4000};
constexpr BenchmarkMaterial castIron{"castIron", 1.0e11, 0.25, 7000};

inline double sphereMass(const BenchmarkMaterial& material, double radius) {
    return 4.0 / 3.0 * std::numbers::pi * radius * radius * radius * material.density;
}

inline DemBody body(const BenchmarkMaterial& material, double radius, const Vec3& position,
                    const Vec3& velocity, const Vec3& spin = Vec3::Zero()) {
    return {{position, velocity, spin, radius}, sphereMass(material, radius)};
}

/// Two spheres moving head on along x with the given velocities, a small gap apart.
inline ImpactScene pairScene(const BenchmarkMaterial& a, double radiusA, double velocityA,
                             const BenchmarkMaterial& b, double radiusB, double velocityB,
                             const SoftContactLaw& law) {
    const double gap = 1e-3 * std::min(radiusA, radiusB);
    ImpactScene scene;
    scene.first = body(a, radiusA, {-radiusA - gap, 0, 0}, {velocityA, 0, 0});
    scene.second = body(b, radiusB, {radiusB, 0, 0}, {velocityB, 0, 0});
    scene.pair = elasticPair(a.elastic(), radiusA, scene.first.mass, b.elastic(), radiusB,
                             scene.second->mass);
    scene.law = law;
    return scene;
}

/// A sphere a small gap from the rigid wall x = 0, moving towards it (normal −x into the gas).
inline ImpactScene wallScene(const BenchmarkMaterial& material, double radius, const Vec3& velocity,
                             const SoftContactLaw& law) {
    const double gap = 1e-3 * radius;
    ImpactScene scene;
    scene.first = body(material, radius, {-radius - gap, 0, 0}, velocity);
    scene.wallNormal = -Vec3::UnitX();
    scene.pair = sphereWallPair(material.elastic(), radius, scene.first.mass, rigidMaterial());
    scene.law = law;
    return scene;
}

} // namespace slides::test
