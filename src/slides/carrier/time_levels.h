// TimeLevels: which written levels of a carrier's time series bracket a run time, and a cache
// that holds at most the levels a step needs, reading the next one ahead on a background thread.
//
// Reference: linear interpolation in time between the two written levels t_a ≤ s ≤ t_b,
// U(s) = (1 − θ) U_a + θ U_b, θ = (s − t_a)/(t_b − t_a), ∂U/∂t = (U_b − U_a)/(t_b − t_a): second
// order in the write interval (error ≤ Δt² max|∂²U/∂t²|/8). Run time t maps to series time
// s = t from the first level; with a cycle of period P, s = t mod P and the last level is followed
// by the first again at P (levels at P or later repeat the first and are left out).
//
//     carrier { type foamField; foamFieldCoeffs { times (0.1 0.5); cycle 0.4; } }
#pragma once

#include <cmath>
#include <cstddef>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <vector>

namespace slides {

/// The two levels around a time: U = (1 − weight) U_before + weight U_after.
struct LevelBracket {
    std::size_t before = 0, after = 0;
    double weight = 0;   ///< θ in [0, 1]
    double interval = 0; ///< t_after − t_before [s]
};

class TimeLevels {
public:
    /// offsets: the written times less the first (ascending, first 0); period: the cycle's.
    TimeLevels(std::vector<double> offsets, std::optional<double> period);

    std::size_t size() const { return offsets_.size(); }
    /// The last run time the series covers: infinite with a cycle.
    double end() const { return period_ ? INFINITY : offsets_.back(); }
    /// The levels around run time t ∈ [0, end()]: t_before ≤ s < t_after (at the series' end,
    /// s = t_after).
    LevelBracket bracket(double time) const;
    /// At a written time (weight 0), the same value as the interval that ends there: weight 1.
    std::optional<LevelBracket> endingAt(const LevelBracket& bracket) const;
    /// The indices of the levels an interval of run times [start, end] needs, in order: from
    /// t_before of start to t_after of end, where an end on a written time needs no later one.
    std::vector<std::size_t> spanning(double start, double end) const;
    /// The level after `index` (the first again after the last, with a cycle).
    std::optional<std::size_t> next(std::size_t index) const;

private:
    std::vector<double> offsets_;
    std::optional<double> period_;
};

/// The levels of a series held in memory: those a step's interval needs (two, or three when
/// a written time falls inside the step), and the next one read ahead on a background thread
/// while the particles move, if that keeps at most three. Thread-safe: samplers take their
/// levels by shared pointer, so a level dropped by hold() lives until its last batch ends.
template <typename Level> class LevelCache {
public:
    using Reader = std::function<std::shared_ptr<const Level>(std::size_t index)>;

    /// readAhead: read the level following the held ones on a background thread.
    LevelCache(TimeLevels levels, Reader read, bool readAhead = true)
        : levels_(std::move(levels)), read_(std::move(read)), readAhead_(readAhead) {}
    ~LevelCache() {
        if (ahead_.valid()) ahead_.wait();
    }

    const TimeLevels& levels() const { return levels_; }

    /// Holds the levels that run times in [start, end] need, reading what is missing, and starts
    /// reading the following level ahead.
    void hold(double start, double end) {
        const std::vector<std::size_t> wanted = levels_.spanning(start, end);
        std::map<std::size_t, std::shared_ptr<const Level>> held;
        std::lock_guard lock(mutex_);
        for (const std::size_t index : wanted) held[index] = take(index);
        held_ = std::move(held);
        const auto following = levels_.next(wanted.back());
        if (ahead_.valid() && (!following || aheadIndex_ != *following))
            ahead_.get(); // read for another interval (a jump back in time): dropped
        if (readAhead_ && !ahead_.valid() && following && !held_.contains(*following) &&
            held_.size() < 3) {
            aheadIndex_ = *following;
            ahead_ = std::async(std::launch::async, read_, *following);
        }
    }

    /// The levels around run time t, and the bracket: held ones, or read now (then not kept).
    /// At a written time ending the held interval, the interval that ends there.
    struct Pair {
        std::shared_ptr<const Level> before, after;
        LevelBracket bracket;
    };
    Pair at(double time) {
        LevelBracket bracket = levels_.bracket(time);
        std::lock_guard lock(mutex_);
        if (const auto ending = levels_.endingAt(bracket);
            ending && !held_.contains(bracket.after) && held_.contains(ending->before))
            bracket = *ending;
        const auto held = [&](std::size_t index) {
            const auto found = held_.find(index);
            return found != held_.end() ? found->second : read_(index);
        };
        return {held(bracket.before), held(bracket.after), bracket};
    }

    /// Levels in memory now, the one being read ahead included.
    std::size_t heldCount() const {
        std::lock_guard lock(mutex_);
        return held_.size() + (ahead_.valid() ? 1 : 0);
    }

private:
    /// Level index from those held, the read-ahead one, or the files.
    std::shared_ptr<const Level> take(std::size_t index) {
        if (const auto found = held_.find(index); found != held_.end()) return found->second;
        if (ahead_.valid() && aheadIndex_ == index) return ahead_.get();
        return read_(index);
    }

    TimeLevels levels_;
    Reader read_;
    bool readAhead_;
    mutable std::mutex mutex_;
    std::map<std::size_t, std::shared_ptr<const Level>> held_;
    std::future<std::shared_ptr<const Level>> ahead_;
    std::size_t aheadIndex_ = 0;
};

} // namespace slides
