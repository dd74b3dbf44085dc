#include "slides/integrate/adaptive_runge_kutta_batch.h"

#include "slides/integrate/adaptive_runge_kutta.h"
#include "slides/integrate/integrator.h"

#include <vector>

namespace slides {

AdaptiveSteps advanceAdaptiveBatch(const AdaptiveBatch& batch, double time, double tolerance,
                                   const DragParameters& drag, const Vec3& bodyAcceleration,
                                   const CarrierField& carrier) {
    AdaptiveSteps steps;
    struct Particle {
        std::size_t index;
        MotionState state;
        double done, trial;
        std::array<MotionState, 7> k; ///< the stage slopes
        double step;
        std::int32_t location; ///< the carrier's cell of the last stage, when it keeps them
        bool knowsFirstSlope;  ///< k₁ at the state: from the last sub-step's k₇, or a rejection
    };
    const auto& h = batch.stepLength;
    const bool species = !batch.density.empty();
    std::vector<Particle> active;
    for (std::size_t i = 0; i < batch.position.size(); ++i) {
        if (!(h[i] > 0)) continue;
        MotionState state;
        state << batch.position[i], batch.velocity[i];
        const double trial =
            !batch.trialStep.empty() && batch.trialStep[i] > 0 ? batch.trialStep[i] : h[i];
        const std::int32_t location = batch.locations.empty() ? -1 : batch.locations[i];
        Particle particle{i, state, 0.0, trial, {}, 0.0, location, false};
        particle.k.fill(MotionState::Zero());
        active.push_back(particle);
    }
    std::vector<std::size_t> members; ///< the active particles a stage samples
    std::vector<Vec3> points;
    std::vector<std::int32_t> locations;
    std::vector<MotionState> stages;
    CarrierSample gas;
    while (!active.empty()) {
        for (Particle& p : active) p.step = std::min(p.trial, h[p.index] - p.done);
        for (int s = 0; s < DormandPrince::stages; ++s) {
            members.clear();
            for (std::size_t n = 0; n < active.size(); ++n)
                if (s > 0 || !active[n].knowsFirstSlope) members.push_back(n);
            stages.resize(members.size());
            points.resize(members.size());
            locations.resize(members.size());
            for (std::size_t m = 0; m < members.size(); ++m) {
                const Particle& p = active[members[m]];
                stages[m] = stageState(p.state, p.k, s, p.step);
                points[m] = stages[m].head<3>();
                locations[m] = p.location;
            }
            carrier.sampleFrom(points, locations, time, CarrierNeeds{}, gas);
            for (std::size_t m = 0; m < members.size(); ++m) {
                Particle& p = active[members[m]];
                p.location = locations[m];
                if (!batch.eddyVelocity.empty()) gas.velocity[m] += batch.eddyVelocity[p.index];
                const Vec3 v = stages[m].tail<3>();
                const double slip = (gas.velocity[m] - v).norm();
                const double tau = species
                                       ? dragResponseTime(drag.withDensity(batch.density[p.index]),
                                                          batch.radius[p.index], slip)
                                       : dragResponseTime(drag, batch.radius[p.index], slip);
                Vec3 acceleration =
                    particleAcceleration(gas.velocity[m], v, tau,
                                         species ? batch.acceleration[p.index] : bodyAcceleration);
                if (!batch.lorentz.empty()) {
                    const LorentzRates& rates = batch.lorentz[p.index];
                    acceleration += rates.electricAcceleration + v.cross(rates.gyration);
                }
                p.k[s] << v, acceleration;
                p.knowsFirstSlope = true;
            }
        }
        // The last stage sampled every active particle, in order: gas.velocity[n] is particle n's.
        std::size_t kept = 0;
        for (std::size_t n = 0; n < active.size(); ++n) {
            Particle& p = active[n];
            MotionState next, error;
            combineStages(p.state, p.k, p.step, next, error);
            const double size =
                scaledError(error, errorScale(tolerance, batch.radius[p.index], p.state, next,
                                              gas.velocity[n].norm()));
            ++steps.attempted;
            const double length = h[p.index];
            const double proposed = p.trial; // before the end of the global step cut it
            if (keepsStep(size, p.step, length)) {
                p.state = next;
                p.done += p.step;
                p.k[0] = p.k[6]; // first same as last: c₇ = 1 and a₇ = b, so k₇ = f(next)
            } else {
                ++steps.rejected;
            }
            p.trial = p.step * stepFactor(size);
            if (p.done < length) {
                active[kept++] = p;
                continue;
            }
            batch.position[p.index] = p.state.head<3>();
            batch.velocity[p.index] = p.state.tail<3>();
            // Its last stage sampled the carrier at the end (Dormand–Prince: c₇ = 1, a₇ = b).
            if (!batch.locations.empty()) batch.locations[p.index] = p.location;
            // A last sub-step shortened to end the global step says little of the next one.
            if (!batch.trialStep.empty())
                batch.trialStep[p.index] = std::max(p.trial, p.step < proposed ? proposed : 0.0);
        }
        active.resize(kept);
    }
    return steps;
}

} // namespace slides
