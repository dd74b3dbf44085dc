#include "slides/integrate/injector_set.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace slides {

InjectorSet::InjectorSet(const std::vector<InjectorSettings>& injectors, bool avoidOverlap) {
    for (const InjectorSettings& settings : injectors)
        injectors_.emplace_back(settings, avoidOverlap);
}

void InjectorSet::injectUntil(double until, double time, const CarrierField& carrier,
                              ParticleCloud& cloud) {
    for (Injector& injector : injectors_) injector.injectUntil(until, time, carrier, cloud);
}

long InjectorSet::injected() const {
    return std::accumulate(
        injectors_.begin(), injectors_.end(), 0L,
        [](long sum, const Injector& injector) { return sum + injector.injected(); });
}

void InjectorSet::resumeAt(double time, long injected) {
    if (injectors_.size() == 1) return injectors_[0].resumeAfter(injected);
    for (Injector& injector : injectors_) injector.resumeAfter(injector.dueBefore(time));
    if (this->injected() != injected)
        throw std::logic_error("the checkpoint's injected count does not match its time");
}

bool InjectorSet::finished() const {
    return std::all_of(injectors_.begin(), injectors_.end(),
                       [](const Injector& injector) { return injector.finished(); });
}

void InjectorSet::setStartStates(ParticleCloud& cloud, std::size_t from) const {
    for (const Injector& injector : injectors_) injector.setStartStates(cloud, from);
}

double InjectorSet::injectionTime(ParticleId id) const {
    return injectors_[static_cast<std::size_t>(injectorOf(id))].injectionTime(id);
}

std::int32_t InjectorSet::injectorOf(ParticleId id) const {
    for (std::size_t i = 0; i < injectors_.size(); ++i)
        if (injectors_[i].owns(id)) return static_cast<std::int32_t>(i);
    throw std::logic_error("a particle id of no injector");
}

} // namespace slides
