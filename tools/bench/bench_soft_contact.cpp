// Cost of the soft-sphere narrow phase: sphereSphereLoad (Hertz normal force with damping,
// Mindlin spring with history and Coulomb limit, torques) per contact, and the sphere–wall load,
// on the granular-gas benchmark's material (tools/bench/granular-gas/README.md: R = 1 mm,
// E = 1e7 Pa, ν = 0.3, LIGGGHTS' damping for e = 0.9, μ = 0.3), 1e4 contacts of random
// overlap (up to 2 % of R), velocity and spin, each with its own spring.
//
//     build/tools/bench/bench_soft_contact
// items_per_second is contact evaluations per second, one thread.
#include "slides/collide/soft_sphere_pair.h"

#include <benchmark/benchmark.h>

#include <numbers>
#include <random>
#include <vector>

namespace {

constexpr double radius = 1e-3;

struct Contacts {
    std::vector<slides::ContactSphere> first, second;
    std::vector<slides::TangentialSpring> springs;
};

Contacts randomContacts(int count) {
    std::mt19937_64 random(42);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const auto vector = [&](double scale) -> slides::Vec3 {
        return slides::Vec3(unit(random), unit(random), unit(random)) * scale;
    };
    Contacts contacts;
    for (int i = 0; i < count; ++i) {
        const slides::Vec3 direction = vector(1.0).normalized();
        const double overlap = 0.02 * radius * (0.5 + 0.5 * unit(random));
        contacts.first.push_back(
            {direction * (2 * radius - overlap), vector(0.5), vector(100.0), radius});
        contacts.second.push_back({slides::Vec3::Zero(), vector(0.5), vector(100.0), radius});
    }
    contacts.springs.resize(count);
    return contacts;
}

void softSphereContacts(benchmark::State& state) {
    const slides::ElasticMaterial material{1e7, 0.3};
    const double mass = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius * 2500;
    const slides::ContactPair pair =
        state.range(1) ? slides::sphereWallPair(material, radius, mass, material)
                       : slides::elasticPair(material, radius, mass, material, radius, mass);
    const slides::SoftContactLaw law{slides::liggghtsDampingRatio(0.9), 0.3};
    Contacts contacts = randomContacts(int(state.range(0)));
    const slides::Vec3 wallPoint(0, 0, -1.99 * radius);
    for (auto _ : state) {
        slides::Vec3 total = slides::Vec3::Zero();
        for (std::size_t i = 0; i < contacts.first.size(); ++i) {
            const slides::ContactLoad load =
                state.range(1)
                    ? slides::sphereWallLoad(pair, law, contacts.second[i], wallPoint,
                                             slides::Vec3::UnitZ(), contacts.springs[i], 1e-5)
                    : slides::sphereSphereLoad(pair, law, contacts.first[i], contacts.second[i],
                                               contacts.springs[i], 1e-5);
            total += load.force + load.torqueOnFirst;
        }
        benchmark::DoNotOptimize(total);
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
    state.SetLabel(state.range(1) ? "sphereWall" : "sphereSphere");
}

BENCHMARK(softSphereContacts)
    ->ArgsProduct({{10000}, {0, 1}})
    ->ArgNames({"contacts", "wall"})
    ->Unit(benchmark::kMicrosecond);

} // namespace
