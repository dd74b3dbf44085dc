// InjectorSet: the run's injectors (`injectors {}`, or the one of `nozzle` + `injection`), each
// owning a block of particle ids (InjectorSettings::firstId), injected in the order listed.
//
// Constant mass flow (Section 5.2.4: "re-injecting particles that leave the domain"): each
// particle of an injector with reinjectEscaped that escapes — leaves the domain box or the
// carrier's mesh; not one that arrives at a surface (sticks or is absorbed), which the jet has
// delivered — is replaced at the end of the step it left in by a new particle of the same
// injector, drawn as its own, with the next of its re-injected ids (InjectorIds). So the
// particles in flight stay as many as without the escapes, step by step.
//
//     injectors { gunA { model disc; ... reinjectEscaped yes; } gunB { model cone; ... } }
#pragma once

#include "slides/integrate/injector.h"

#include <cstdint>
#include <vector>

namespace slides {

class InjectorSet {
public:
    /// avoidOverlap: no particle placed overlapping one near its injector (collisions on).
    explicit InjectorSet(const std::vector<InjectorSettings>& injectors, bool avoidOverlap = false);

    /// Each rank adds only the particles its part of a decomposed mesh holds (a parallel run's
    /// stepper: its cloud is split among the ranks), instead of every particle.
    void splitAmongRanks();
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

    /// Whether any injector replaces its escaped particles.
    bool reinjects() const;
    /// Particle id escaped: its injector replaces it at the next reinjectEscaped, if it does so.
    void noteEscape(ParticleId id);
    /// Adds the replacements of the escapes noted since the last call, at time, injector by
    /// injector, each's in the order of its re-injected ids. Returns how many.
    std::size_t reinjectEscaped(double time, const CarrierField& carrier, ParticleCloud& cloud);
    /// Particles re-injected so far, per injector.
    const std::vector<std::uint64_t>& reinjected() const { return reinjected_; }
    /// Continues after `reinjected` re-injected particles per injector (restart).
    void resumeReinjected(const std::vector<std::uint64_t>& reinjected);

private:
    std::vector<Injector> injectors_;
    InjectorIds ids_;
    std::vector<std::uint64_t> reinjected_; ///< per injector, so far
    std::vector<std::uint64_t> escapes_;    ///< per injector, to replace at the next call
    std::vector<ParticleId> newIds_;        ///< scratch
};

} // namespace slides
