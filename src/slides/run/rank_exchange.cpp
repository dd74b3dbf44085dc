#include "slides/run/rank_exchange.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <stdexcept>

namespace slides {

namespace {

/// Calls visit(array) for every per-particle array that travels: the cloud's, then the step's.
template <typename Visit>
void forEachTravelling(ParticleCloud& cloud, TravellingArrays& step, Visit visit) {
    ParticleCloud::forEachArray(cloud, [&](const char*, auto& array) { visit(array); });
    visit(step.stepLengths);
    visit(step.startPositions);
    visit(step.startVelocities);
    visit(step.startTemperatures);
    visit(step.gasTemperatures);
}

template <typename T> void put(Bytes& bytes, const T& value) {
    const std::size_t at = bytes.size();
    bytes.resize(at + sizeof(T));
    std::memcpy(bytes.data() + at, static_cast<const void*>(&value), sizeof(T));
}

template <typename T> T take(const Bytes& bytes, std::size_t& at) {
    if (at + sizeof(T) > bytes.size()) throw std::logic_error("rank exchange: short message");
    T value;
    std::memcpy(static_cast<void*>(&value), bytes.data() + at, sizeof(T));
    at += sizeof(T);
    return value;
}

/// Removes particles at indices (ascending) by swapping in the last ones, from the cloud and
/// the step's arrays alike.
void removeParticles(ParticleCloud& cloud, TravellingArrays& step,
                     const std::vector<std::size_t>& indices) {
    for (auto i = indices.rbegin(); i != indices.rend(); ++i) {
        const std::size_t index = *i;
        const auto swapOut = [index](auto& array) {
            if (array.empty()) return;
            array[index] = array.back();
            array.pop_back();
        };
        swapOut(step.stepLengths);
        swapOut(step.startPositions);
        swapOut(step.startVelocities);
        swapOut(step.startTemperatures);
        swapOut(step.gasTemperatures);
        cloud.removeAt(index);
    }
}

} // namespace

RankExchange::RankExchange(const RankCarrier& carrier)
    : carrier_(carrier),
      clearance_(carrier.part().mesh(), carrier.part().locator(), carrier.firstProcessorPatch()) {}

bool RankExchange::everyRankEmpty(std::size_t particles) const {
    return ranks().sum(static_cast<std::uint64_t>(particles)) == 0;
}

int RankExchange::patchTowards(int rank) const {
    const auto& patches = carrier_.part().mesh().patches;
    for (int p = carrier_.firstProcessorPatch(); p < static_cast<int>(patches.size()); ++p)
        if (patches[p].neighbourRank == rank) return p;
    return -1;
}

std::int32_t RankExchange::walk(const Vec3& point, std::int32_t location, int& transitFace) const {
    transitFace = -1;
    const FoamCarrier& part = carrier_.part();
    const TetLocation at = part.locator().locateFrom(part.meshPoint(point), location);
    if (at.found()) return at.tet;
    if (at.exitPatch >= carrier_.firstProcessorPatch()) {
        if (at.exitFace >= 0) transitFace = at.exitFace;
        return -2;
    }
    return -3 - at.exitPatch; // −2 when the patch is not known
}

void RankExchange::keepHeldHere(ParticleCloud& cloud, TravellingArrays step) {
    cloud.carrierLocation.assign(cloud.size(), -1);
    std::vector<std::uint8_t> keep;
    carrier_.keepHeldHere(cloud.position, cloud.carrierLocation, keep);
    std::vector<std::size_t> leaving;
    for (std::size_t i = 0; i < cloud.size(); ++i)
        if (!keep[i]) leaving.push_back(i);
    removeParticles(cloud, step, leaving);
}

void RankExchange::exchange(ParticleCloud& cloud, TravellingArrays step, bool startsLocated) {
    const auto start = std::chrono::steady_clock::now();
    const RankCommunicator& ranks = this->ranks();
    const int size = ranks.size();
    const FoamMesh& mesh = carrier_.part().mesh();
    const FoamLocator& locator = carrier_.part().locator();
    forEachTravelling(cloud, step, [&](const auto& array) {
        if (!array.empty() && array.size() != cloud.size())
            throw std::logic_error("rank exchange: a per-particle array of another length");
    });

    // Each walks to its position, unless it surely crossed no processor face; (index, face) of
    // those reaching one.
    std::vector<std::size_t> leaving;
    std::vector<std::pair<std::size_t, int>> transit;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const std::int32_t location = cloud.carrierLocation[i];
        if (startsLocated && location >= 0 && location < locator.tetIndexEnd() &&
            clearance_.stayed(location, carrier_.part().meshPoint(cloud.position[i])))
            continue;
        int face = -1;
        cloud.carrierLocation[i] = walk(cloud.position[i], cloud.carrierLocation[i], face);
        if (face >= 0) transit.emplace_back(i, face);
    }

    const std::size_t stateWidth = cloud.stateWidth;
    for (int round = 0;; ++round) {
        if (ranks.sum(static_cast<std::uint64_t>(transit.size())) == 0) break;
        if (round == 100) { // handed back and forth on a face: lost (every rank stops here)
            for (const auto& [i, face] : transit) cloud.carrierLocation[i] = -2;
            break;
        }
        ++figures_.rounds;
        // Messages: which arrays travel (a bit each, in forEachTravelling order), then per
        // particle its face in the processor patch and those arrays' entries.
        std::uint32_t present = 0, bit = 1;
        forEachTravelling(cloud, step, [&](const auto& array) {
            if (!array.empty()) present |= bit;
            bit <<= 1;
        });
        std::vector<Bytes> outgoing(static_cast<std::size_t>(size));
        for (auto& message : outgoing) put(message, present);
        for (const auto& [i, face] : transit) {
            const FoamPatch& patch = mesh.patches[mesh.facePatch[face]];
            Bytes& message = outgoing[static_cast<std::size_t>(patch.neighbourRank)];
            put(message, static_cast<std::int32_t>(face - patch.start));
            forEachTravelling(cloud, step, [&](const auto& array) {
                if (!array.empty()) put(message, array[i]);
            });
            for (std::size_t s = 0; s < stateWidth; ++s)
                put(message, cloud.modelState[i * stateWidth + s]);
            leaving.push_back(i);
        }
        figures_.particlesSent += transit.size();
        for (const Bytes& message : outgoing)
            if (message.size() > sizeof present) figures_.bytesSent += message.size();
        std::sort(leaving.begin(), leaving.end());
        removeParticles(cloud, step, leaving);
        leaving.clear();
        transit.clear();

        const auto incoming = ranks.exchange(outgoing);
        for (int from = 0; from < size; ++from) {
            const Bytes& message = incoming[static_cast<std::size_t>(from)];
            if (message.size() <= sizeof present) continue;
            std::size_t at = 0;
            const auto arrays = take<std::uint32_t>(message, at);
            const int patch = patchTowards(from);
            if (patch < 0) throw std::logic_error("rank exchange: particles from a non-neighbour");
            while (at < message.size()) {
                const int face = mesh.patches[patch].start + take<std::int32_t>(message, at);
                std::uint32_t flag = 1;
                forEachTravelling(cloud, step, [&](auto& array) {
                    using Entry = typename std::remove_reference_t<decltype(array)>::value_type;
                    if (arrays & flag) array.push_back(take<Entry>(message, at));
                    flag <<= 1;
                });
                for (std::size_t s = 0; s < stateWidth; ++s)
                    cloud.modelState.push_back(take<double>(message, at));
                // On from the cell behind the matching face.
                const std::size_t i = cloud.size() - 1;
                const TetLocation found =
                    locator.locate(carrier_.part().meshPoint(cloud.position[i]), mesh.owner[face]);
                int next = -1;
                if (found.found()) {
                    cloud.carrierLocation[i] = found.tet;
                } else if (found.exitPatch >= carrier_.firstProcessorPatch()) {
                    next = found.exitFace;
                    cloud.carrierLocation[i] = -2;
                } else {
                    cloud.carrierLocation[i] = -3 - found.exitPatch;
                }
                if (next >= 0) transit.emplace_back(i, next);
            }
        }
    }
    figures_.seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace slides
