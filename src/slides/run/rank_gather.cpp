#include "slides/run/rank_gather.h"

#include <algorithm>
#include <cstring>
#include <numeric>

namespace slides {

namespace {

template <typename T> void put(Bytes& bytes, const T& value) {
    const std::size_t at = bytes.size();
    bytes.resize(at + sizeof(T));
    std::memcpy(bytes.data() + at, static_cast<const void*>(&value), sizeof(T));
}

template <typename T> T take(const Bytes& bytes, std::size_t& at) {
    T value;
    std::memcpy(static_cast<void*>(&value), bytes.data() + at, sizeof(T));
    at += sizeof(T);
    return value;
}

/// The particles' arrays (those that are not empty: a bit each in forEachArray order), then the
/// arrivals.
Bytes packed(const RunSnapshot& mine) {
    Bytes bytes;
    const ParticleCloud& cloud = mine.cloud;
    std::uint32_t present = 0, bit = 1;
    ParticleCloud::forEachArray(cloud, [&](const char*, const auto& array) {
        if (!array.empty() && array.size() == cloud.size()) present |= bit;
        bit <<= 1;
    });
    put(bytes, present);
    put(bytes, static_cast<std::uint64_t>(cloud.size()));
    bit = 1;
    ParticleCloud::forEachArray(cloud, [&](const char*, const auto& array) {
        if (present & bit)
            for (const auto& entry : array) put(bytes, entry);
        bit <<= 1;
    });
    put(bytes, static_cast<std::uint64_t>(mine.arrivals.size()));
    for (const Arrival& arrival : mine.arrivals) put(bytes, arrival);
    return bytes;
}

void unpack(const Bytes& bytes, GatheredRun& run) {
    std::size_t at = 0;
    const auto present = take<std::uint32_t>(bytes, at);
    const auto count = take<std::uint64_t>(bytes, at);
    std::uint32_t bit = 1;
    ParticleCloud::forEachArray(run.cloud, [&](const char*, auto& array) {
        using Entry = typename std::remove_reference_t<decltype(array)>::value_type;
        if (present & bit)
            for (std::uint64_t n = 0; n < count; ++n) array.push_back(take<Entry>(bytes, at));
        bit <<= 1;
    });
    const auto arrivals = take<std::uint64_t>(bytes, at);
    for (std::uint64_t n = 0; n < arrivals; ++n) run.arrivals.push_back(take<Arrival>(bytes, at));
}

/// The cloud's arrays put in the order of the particles' ids.
void sortById(ParticleCloud& cloud) {
    std::vector<std::size_t> order(cloud.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return cloud.id[a] < cloud.id[b]; });
    ParticleCloud::forEachArray(cloud, [&](const char*, auto& array) {
        if (array.size() != order.size()) return;
        auto sorted = array;
        for (std::size_t n = 0; n < order.size(); ++n) sorted[n] = array[order[n]];
        array = std::move(sorted);
    });
}

} // namespace

GatheredRun gatherRun(const RunSnapshot& mine, const RankCommunicator& ranks, std::size_t exits,
                      std::size_t surfaces) {
    GatheredRun run;
    run.counters = mine.counters;
    run.neighbourListBuilds = mine.neighbourListBuilds;
    RunCounters& counters = run.counters;
    counters.escapedThrough.resize(std::max(exits, counters.escapedThrough.size()), 0);
    counters.rebounds.resize(std::max(surfaces, counters.rebounds.size()), 0);
    ranks.sum(counters.escapedThrough);
    ranks.sum(counters.rebounds);
    std::array<std::uint64_t, 3> sums{static_cast<std::uint64_t>(counters.escaped),
                                      counters.particleSteps,
                                      static_cast<std::uint64_t>(counters.collisions)};
    ranks.sum(sums);
    counters.escaped = static_cast<long>(sums[0]);
    counters.particleSteps = sums[1];
    counters.collisions = static_cast<long>(sums[2]);
    for (const Bytes& part : ranks.gather(packed(mine))) unpack(part, run);
    sortById(run.cloud);
    std::sort(run.arrivals.begin(), run.arrivals.end(),
              [](const Arrival& a, const Arrival& b) { return a.id < b.id; });
    return run;
}

} // namespace slides
