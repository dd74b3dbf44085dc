#include "slides/integrate/adaptive_runge_kutta_batch.h"

#include "slides/integrate/adaptive_runge_kutta.h"

#include <vector>

namespace slides {

AdaptiveSteps advanceAdaptiveBatch(std::span<Vec3> position, std::span<Vec3> velocity,
                                   std::span<const double> radius, std::span<const double> h,
                                   double time, double tolerance, const DragParameters& drag,
                                   const Vec3& bodyAcceleration, const CarrierField& carrier) {
    AdaptiveSteps steps;
    struct Particle {
        std::size_t index;
        MotionState state;
        double done, trial;
        std::array<MotionState, 7> k; ///< the stage slopes
        double step;
    };
    std::vector<Particle> active;
    for (std::size_t i = 0; i < position.size(); ++i) {
        if (!(h[i] > 0)) continue;
        MotionState state;
        state << position[i], velocity[i];
        Particle particle{i, state, 0.0, h[i], {}, 0.0};
        particle.k.fill(MotionState::Zero());
        active.push_back(particle);
    }
    std::vector<Vec3> points;
    std::vector<MotionState> stages;
    CarrierSample gas;
    while (!active.empty()) {
        for (Particle& p : active) p.step = std::min(p.trial, h[p.index] - p.done);
        for (int s = 0; s < DormandPrince::stages; ++s) {
            stages.resize(active.size());
            points.resize(active.size());
            for (std::size_t n = 0; n < active.size(); ++n) {
                stages[n] = stageState(active[n].state, active[n].k, s, active[n].step);
                points[n] = stages[n].head<3>();
            }
            carrier.sample(points, time, CarrierNeeds{}, gas);
            for (std::size_t n = 0; n < active.size(); ++n) {
                const Vec3 v = stages[n].tail<3>();
                const Vec3 slip = gas.velocity[n] - v;
                const double tau = dragResponseTime(drag, radius[active[n].index], slip.norm());
                active[n].k[s] << v, slip / tau + bodyAcceleration;
            }
        }
        std::size_t kept = 0;
        for (std::size_t n = 0; n < active.size(); ++n) {
            Particle& p = active[n];
            MotionState next, error;
            combineStages(p.state, p.k, p.step, next, error);
            const double size = scaledError(error, errorScale(tolerance, radius[p.index], p.state,
                                                              next, gas.velocity[n].norm()));
            ++steps.attempted;
            const double length = h[p.index];
            if (size <= 1 || p.step <= 1e-12 * length) { // accepted, or too small to shrink
                p.state = next;
                p.done += p.step;
            } else {
                ++steps.rejected;
            }
            p.trial = p.step * stepFactor(size);
            if (p.done < length) {
                active[kept++] = p;
            } else {
                position[p.index] = p.state.head<3>();
                velocity[p.index] = p.state.tail<3>();
            }
        }
        active.resize(kept);
    }
    return steps;
}

} // namespace slides
