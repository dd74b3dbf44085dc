// InjectorSet: the run's injectors (`injectors {}`, or the one of `nozzle` + `injection`), each
// owning a block of particle ids (InjectorSettings::firstId), injected in the order listed.
//
//     injectors { gunA { model disc; ... } gunB { model cone; ... } }
#pragma once

#include "slides/integrate/injector.h"

#include <cstdint>
#include <vector>

namespace slides {

class InjectorSet {
public:
    /// avoidOverlap: no particle placed overlapping one near its injector (collisions on).
    explicit InjectorSet(const std::vector<InjectorSettings>& injectors, bool avoidOverlap = false);

    /// Adds every particle due before `until` of every injector, injector by injector.
    void injectUntil(double until, double time, const CarrierField& carrier, ParticleCloud& cloud);
    /// Particles injected so far, all injectors.
    long injected() const;
    /// Continues a run stopped at `time` after `injected` particles (restart): each injector
    /// resumes after its particles due before then.
    void resumeAt(double time, long injected);
    bool finished() const;
    /// The spins and temperatures files give the particles at indices [from, size) of cloud.
    void setStartStates(ParticleCloud& cloud, std::size_t from) const;
    /// Time at which particle id enters [s].
    double injectionTime(ParticleId id) const;
    /// The index of the injector particle id came from.
    std::int32_t injectorOf(ParticleId id) const;
    const std::vector<Injector>& injectors() const { return injectors_; }

private:
    std::vector<Injector> injectors_;
};

} // namespace slides
