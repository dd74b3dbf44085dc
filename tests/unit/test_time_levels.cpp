// ctest-labels: transient carrier
// The levels of a time series (carrier/time_levels.h): which two bracket a run time and with
// what weight, which a step's interval needs (two inside a write interval, three across a
// written time, none beyond an end that falls on one), the cycle's wrap from the last level to
// the first, and the cache's bound of three levels in memory with the next one read ahead.
#include "slides/carrier/time_levels.h"

#include <gtest/gtest.h>

#include <atomic>

namespace slides {
namespace {

const std::vector<double> offsets{0, 0.1, 0.2, 0.4}; // unequal intervals

TEST(TimeLevels, BracketsARunTimeWithItsLinearWeight) {
    const TimeLevels levels(offsets, std::nullopt);
    const LevelBracket middle = levels.bracket(0.3);
    EXPECT_EQ(middle.before, 2u);
    EXPECT_EQ(middle.after, 3u);
    EXPECT_DOUBLE_EQ(middle.weight, 0.5);
    EXPECT_DOUBLE_EQ(middle.interval, 0.2);
    const LevelBracket onLevel = levels.bracket(0.1); // a written time opens its interval
    EXPECT_EQ(onLevel.before, 1u);
    EXPECT_EQ(onLevel.weight, 0.0);
    const auto ending = levels.endingAt(onLevel); // ... and closes the one before, weight 1
    ASSERT_TRUE(ending);
    EXPECT_EQ(ending->before, 0u);
    EXPECT_EQ(ending->weight, 1.0);
    const LevelBracket last = levels.bracket(0.4); // the series' end: the last interval
    EXPECT_EQ(last.before, 2u);
    EXPECT_EQ(last.weight, 1.0);
    EXPECT_THROW(levels.bracket(0.41), std::out_of_range);
    EXPECT_EQ(levels.end(), 0.4);
}

TEST(TimeLevels, AStepNeedsTheLevelsAroundItsInterval) {
    const TimeLevels levels(offsets, std::nullopt);
    EXPECT_EQ(levels.spanning(0.12, 0.18), (std::vector<std::size_t>{1, 2}));
    EXPECT_EQ(levels.spanning(0.15, 0.25), (std::vector<std::size_t>{1, 2, 3}));
    EXPECT_EQ(levels.spanning(0.1, 0.2), (std::vector<std::size_t>{1, 2})); // on written times
    EXPECT_EQ(levels.next(3), std::nullopt);
}

TEST(TimeLevels, CycleWrapsFromTheLastLevelToTheFirst) {
    // Period 0.5: level 0 follows level 3 at 0.5, so t = 0.45 is halfway between them; a level
    // written at the period itself repeats the first and is left out.
    const TimeLevels levels(offsets, 0.5);
    const LevelBracket wrap = levels.bracket(0.45);
    EXPECT_EQ(wrap.before, 3u);
    EXPECT_EQ(wrap.after, 0u);
    EXPECT_DOUBLE_EQ(wrap.weight, 0.5);
    EXPECT_DOUBLE_EQ(wrap.interval, 0.1);
    const LevelBracket later = levels.bracket(1.35); // 1.35 mod 0.5 = 0.35
    EXPECT_EQ(later.before, 2u);
    EXPECT_NEAR(later.weight, 0.75, 1e-12);
    EXPECT_EQ(levels.spanning(0.45, 0.55), (std::vector<std::size_t>{3, 0, 1}));
    EXPECT_EQ(levels.end(), INFINITY);
    EXPECT_EQ(TimeLevels({0, 0.1, 0.2, 0.3}, 0.3).size(), 3u);
}

TEST(LevelCache, HoldsAtMostThreeLevelsAndReadsTheNextAhead) {
    // 200 levels stepped through in steps of 0.3 write intervals: never more than three in
    // memory (the cache's count, and the levels alive), every level read once, in order.
    std::vector<double> many;
    for (int n = 0; n < 200; ++n) many.push_back(0.01 * n);
    std::atomic<int> alive = 0, reads = 0, largest = 0;
    struct Level {
        std::atomic<int>* alive;
        explicit Level(std::atomic<int>* count) : alive(count) { ++*alive; }
        ~Level() { --*alive; }
    };
    LevelCache<Level> cache(TimeLevels(many, std::nullopt), [&](std::size_t) {
        ++reads;
        return std::make_shared<const Level>(&alive);
    });
    std::size_t mostHeld = 0;
    for (double t = 0; t + 0.003 <= 1.99; t += 0.003) {
        cache.hold(t, t + 0.003);
        const auto pair = cache.at(t + 0.0015);
        EXPECT_LE(pair.bracket.weight, 1.0);
        mostHeld = std::max(mostHeld, cache.heldCount());
        largest = std::max(largest.load(), alive.load());
    }
    EXPECT_EQ(mostHeld, 3u);
    EXPECT_LE(largest, 3);
    EXPECT_EQ(reads, 200);
}

} // namespace
} // namespace slides
