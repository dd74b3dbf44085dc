#include "slides/integrate/injector_set.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace slides {

InjectorSet::InjectorSet(const std::vector<InjectorSettings>& injectors, bool avoidOverlap)
    : ids_(injectorIdsOf(injectors)), reinjected_(injectors.size(), 0),
      escapes_(injectors.size(), 0) {
    for (const InjectorSettings& settings : injectors)
        injectors_.emplace_back(settings, avoidOverlap);
}

bool InjectorSet::reinjects() const {
    return std::any_of(injectors_.begin(), injectors_.end(), [](const Injector& injector) {
        return injector.settings().injection.reinjectEscaped;
    });
}

void InjectorSet::noteEscape(ParticleId id) {
    const auto injector = static_cast<std::size_t>(ids_.injectorOf(id));
    if (injectors_[injector].settings().injection.reinjectEscaped) ++escapes_[injector];
}

std::size_t InjectorSet::reinjectEscaped(double time, const CarrierField& carrier,
                                         ParticleCloud& cloud) {
    std::size_t added = 0;
    for (std::size_t j = 0; j < injectors_.size(); ++j) {
        newIds_.resize(escapes_[j]);
        for (std::uint64_t k = 0; k < escapes_[j]; ++k)
            newIds_[k] = ids_.reinjectedId(j, reinjected_[j] + k);
        injectors_[j].reinject(newIds_, time, carrier, cloud);
        reinjected_[j] += escapes_[j];
        added += escapes_[j];
        escapes_[j] = 0;
    }
    return added;
}

void InjectorSet::resumeReinjected(const std::vector<std::uint64_t>& reinjected) {
    if (reinjected.empty()) return; // a checkpoint of a run that re-injects nothing
    if (reinjected.size() != injectors_.size())
        throw std::logic_error("the checkpoint's re-injected counts do not match the injectors");
    reinjected_ = reinjected;
}

void InjectorSet::splitAmongRanks() {
    for (Injector& injector : injectors_) injector.splitAmongRanks();
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

std::int32_t InjectorSet::injectorOf(ParticleId id) const { return ids_.injectorOf(id); }

} // namespace slides
