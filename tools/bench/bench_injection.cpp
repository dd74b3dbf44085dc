// Cost of overlap-free injection (integrate/injector.h, integrate/nearby_spheres.h) from a
// 10 mm square patch: particles of 20 µm placed with and without the rule (collisions on and
// off). `rate`: 100 particles a step of 10 µs leaving the patch at 0.1 m/s, so that about 4000
// lie within the contact distance of it in the steady state (counter `nearPatch`) among the
// 40000 of the 400 steps; `allAtStart`: 20000 placed at once (a quarter of the patch covered).
//
//     build/tools/bench/bench_injection --benchmark_counters_tabular=true
// items_per_second is particles injected per second (the cloud moved on each step included).
#include "slides/integrate/injector.h"

#include <benchmark/benchmark.h>

namespace {

using slides::Vec3;

/// Still gas with one patch, the square [0, 0.01]² in z = 0 seen from z > 0.
class SquarePatchCarrier : public slides::CarrierField {
public:
    void sample(std::span<const Vec3> points, double, slides::CarrierNeeds needs,
                slides::CarrierSample& out) const override {
        out.resize(points.size(), needs);
        for (auto& u : out.velocity) u.setZero();
    }
    std::vector<slides::PatchTriangle> patchTriangles(const std::string&) const override {
        const double side = 0.01;
        return {{Vec3(0, 0, 0), Vec3(side, 0, 0), Vec3(side, side, 0)},
                {Vec3(0, 0, 0), Vec3(side, side, 0), Vec3(0, side, 0)}};
    }
    std::string describe() const override { return "still gas with a square patch"; }
};

constexpr double particleRadius = 20e-6, stepLength = 1e-5;

slides::InjectorSettings patchInjector(slides::InjectionMode mode, long count) {
    slides::InjectorSettings settings;
    settings.model = slides::InjectionModel::patch;
    settings.patch = {"square", Vec3(0, 0, 0.1)};
    settings.injection.mode = mode;
    settings.injection.rate = 100 / stepLength;
    settings.count = count;
    settings.radius.value = particleRadius;
    return settings;
}

/// The particles of cloud whose centres lie within two radii of the patch's plane.
double nearPatch(const slides::ParticleCloud& cloud) {
    double near = 0;
    for (const Vec3& x : cloud.position) near += x.z() < 2 * particleRadius ? 1 : 0;
    return near;
}

/// Injects `count` particles over steps of 10 µs, each step moving the cloud on.
void inject(benchmark::State& state, slides::InjectionMode mode, long count) {
    const bool avoidOverlap = state.range(0) != 0;
    const SquarePatchCarrier carrier;
    slides::ParticleCloud cloud;
    double near = 0;
    for (auto _ : state) {
        slides::Injector injector(patchInjector(mode, count), avoidOverlap);
        cloud = slides::ParticleCloud();
        for (double t = 0; !injector.finished(); t += stepLength) {
            injector.injectUntil(t + stepLength, t, carrier, cloud);
            for (std::size_t i = 0; i < cloud.size(); ++i)
                cloud.position[i] += stepLength * cloud.velocity[i];
        }
        state.PauseTiming();
        near = nearPatch(cloud);
        state.ResumeTiming();
    }
    state.SetItemsProcessed(state.iterations() * count);
    state.counters["nearPatch"] = near;
    state.counters["collisionsOn"] = avoidOverlap;
}

void rate(benchmark::State& state) { inject(state, slides::InjectionMode::rate, 40000); }
void allAtStart(benchmark::State& state) {
    inject(state, slides::InjectionMode::allAtStart, 20000);
}

} // namespace

BENCHMARK(rate)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(allAtStart)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(3);
