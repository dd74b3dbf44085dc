// The count of the adaptive integrator's Dormand–Prince sub-steps (integrate/
// adaptive_runge_kutta_batch.h; Section 4.2.3, Algorithm 2): its cost, reported in summary.json
// as performance.adaptiveSteps.
//
//     time { integrator adaptiveRungeKutta; tolerance 1e-6; }
#pragma once

namespace slides {

struct AdaptiveSteps {
    long attempted = 0; ///< Dormand–Prince steps tried, all particles
    long rejected = 0;  ///< of them, the ones whose error exceeded the tolerance

    AdaptiveSteps& operator+=(const AdaptiveSteps& other) {
        attempted += other.attempted;
        rejected += other.rejected;
        return *this;
    }
};

} // namespace slides
