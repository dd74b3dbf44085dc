#include "slides/carrier/time_levels.h"

#include <algorithm>

namespace slides {

TimeLevels::TimeLevels(std::vector<double> offsets, std::optional<double> period)
    : offsets_(std::move(offsets)), period_(period) {
    if (period_)
        offsets_.erase(std::lower_bound(offsets_.begin(), offsets_.end(), *period_),
                       offsets_.end());
    if (offsets_.size() < 2) throw std::logic_error("a time series needs two levels");
}

LevelBracket TimeLevels::bracket(double time) const {
    double s = time;
    if (period_) s -= std::floor(time / *period_) * *period_;
    if (!(s >= 0) || (!period_ && s > offsets_.back()))
        throw std::out_of_range("time outside the series");
    // The last level at or before s (the one before the last at its very end, without a cycle).
    const auto upper = std::upper_bound(offsets_.begin(), offsets_.end(), s);
    std::size_t before = static_cast<std::size_t>(upper - offsets_.begin()) - 1;
    if (!period_ && before + 1 == offsets_.size()) --before;
    const bool wraps = before + 1 == offsets_.size();
    const std::size_t after = wraps ? 0 : before + 1;
    const double interval = (wraps ? *period_ : offsets_[after]) - offsets_[before];
    return {before, after, std::clamp((s - offsets_[before]) / interval, 0.0, 1.0), interval};
}

std::optional<LevelBracket> TimeLevels::endingAt(const LevelBracket& bracket) const {
    if (bracket.weight != 0) return std::nullopt;
    if (bracket.before == 0 && !period_) return std::nullopt;
    const std::size_t before = bracket.before == 0 ? size() - 1 : bracket.before - 1;
    const double interval = bracket.before == 0 ? *period_ - offsets_[before]
                                                : offsets_[bracket.before] - offsets_[before];
    return LevelBracket{before, bracket.before, 1.0, interval};
}

std::optional<std::size_t> TimeLevels::next(std::size_t index) const {
    if (index + 1 < offsets_.size()) return index + 1;
    if (period_) return 0;
    return std::nullopt;
}

std::vector<std::size_t> TimeLevels::spanning(double start, double end) const {
    const LevelBracket first = bracket(start);
    LevelBracket last = bracket(std::max(start, end));
    if (const auto ending = endingAt(last); ending && end > start) last = *ending;
    std::vector<std::size_t> indices{first.before};
    // Forward from the first bracket to the last one's later level (through the cycle's wrap).
    for (std::size_t index = first.before; index != last.after && indices.size() <= size();) {
        index = *next(index);
        indices.push_back(index);
    }
    return indices;
}

} // namespace slides
