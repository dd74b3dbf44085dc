// Time settings: the time step, the end of the run and the integrator (`time {}`).
//
//     time { dt 1e-5; endTime 0.1; stopWhenAllDone yes; integrator exponentialMidpoint; }
//     time { endTime 0.1; integrator adaptiveRungeKutta; tolerance 1e-6; }
#pragma once

#include "slides/integrate/integrator.h"

namespace slides {

struct TimeSettings {
    double dt = 0;               ///< [s]; 0: the scene analysis chooses it
    double endTime = 0;          ///< [s]; the run also stops earlier when stopWhenAllDone
    bool stopWhenAllDone = true; ///< stop once every particle has arrived or escaped
    Integrator integrator = Integrator::exponentialMidpoint;
    /// TOL of adaptiveRungeKutta's step control (Eq. 4.29): each sub-step's error estimate
    /// relative to the particle's radius and speed (integrate/adaptive_runge_kutta.h)
    double tolerance = 1e-6;
};

} // namespace slides
