#include "slides/carrier/foam_shared_points.h"

#include "slides/carrier/foam_file.h"
#include "slides/carrier/foam_interpolation.h"
#include "slides/core/error.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <unordered_map>

namespace slides {

namespace {

template <typename T> void put(std::vector<std::byte>& bytes, const T& value) {
    const std::size_t at = bytes.size();
    bytes.resize(at + sizeof(T));
    std::memcpy(bytes.data() + at, static_cast<const void*>(&value), sizeof(T));
}

template <typename T> T take(const std::vector<std::byte>& bytes, std::size_t& at) {
    T value;
    std::memcpy(static_cast<void*>(&value), bytes.data() + at, sizeof(T));
    at += sizeof(T);
    return value;
}

bool givesBoundaryValues(PatchType type) {
    return type == PatchType::patch || type == PatchType::wall;
}

/// A sample as the whole mesh numbers it: cells first, then cellCount + boundary face.
struct SampleRecord {
    std::int64_t point; ///< whole-mesh point
    std::int64_t key;   ///< whole-mesh sample
    Vec3 position;
};

} // namespace

PartAddressing readPartAddressing(const std::filesystem::path& partDirectory,
                                  const FoamMesh& mesh) {
    const auto dir = partDirectory / "constant" / "polyMesh";
    PartAddressing addressing;
    addressing.points = FoamFile(dir / "pointProcAddressing")
                            .list<std::int64_t>(static_cast<long>(mesh.points.size()));
    addressing.cells = FoamFile(dir / "cellProcAddressing").list<std::int64_t>(mesh.cellCount);
    addressing.faces = FoamFile(dir / "faceProcAddressing").list<std::int64_t>(mesh.faceCount());
    for (const std::int64_t face : addressing.faces)
        if (face == 0)
            throw InputError((dir / "faceProcAddressing").string(), 0, "",
                             "face label 0: labels are ±(face + 1)");
    return addressing;
}

SharedPointWeights::SharedPointWeights(const FoamMesh& mesh, const PartAddressing& addressing,
                                       PartAllGather allGather)
    : mesh_(mesh), allGather_(std::move(allGather)) {
    // The whole mesh's cell count, from every part's.
    std::vector<std::byte> count;
    put(count, static_cast<std::int64_t>(mesh.cellCount));
    std::int64_t wholeCells = 0;
    for (const auto& part : allGather_(count)) {
        std::size_t at = 0;
        wholeCells += take<std::int64_t>(part, at);
    }
    // The shared points (on processor patches) and this part's samples of each, as the whole
    // mesh's PointWeights takes them: the cells using the point, its boundary faces.
    std::vector<char> shared(mesh.points.size(), 0);
    for (const FoamPatch& patch : mesh.patches)
        if (patch.type == PatchType::processor)
            for (int f = patch.start; f < patch.start + patch.size; ++f)
                for (const int p : mesh.pointsOf(f)) shared[static_cast<std::size_t>(p)] = 1;
    std::map<int, std::vector<int>> around; // shared point → local samples
    for (int f = 0; f < mesh.faceCount(); ++f) {
        const int patch = mesh.facePatch[f];
        for (const int p : mesh.pointsOf(f)) {
            if (!shared[static_cast<std::size_t>(p)]) continue;
            auto& list = around[p];
            list.push_back(mesh.owner[f]);
            if (f < mesh.internalFaceCount()) list.push_back(mesh.neighbour[f]);
            if (patch >= 0 && givesBoundaryValues(mesh.patches[patch].type))
                list.push_back(mesh.cellCount + f);
        }
    }
    std::vector<std::byte> records;
    std::unordered_map<int, std::size_t> sentIndex;
    for (auto& [p, list] : around) {
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
        for (const int s : list) {
            const bool cell = s < mesh.cellCount;
            const int face = s - mesh.cellCount;
            const std::int64_t key =
                cell ? addressing.cells[static_cast<std::size_t>(s)]
                     : wholeCells + std::abs(addressing.faces[static_cast<std::size_t>(face)]) - 1;
            const auto [slot, added] = sentIndex.try_emplace(s, sent_.size());
            if (added) sent_.push_back(s);
            put(records, SampleRecord{addressing.points[static_cast<std::size_t>(p)], key,
                                      cell ? mesh.cellCentres[s] : mesh.faceCentres[face]});
            put(records, static_cast<std::int64_t>(slot->second));
        }
    }
    // Every part's records: for each whole-mesh point, its samples by key, where their values
    // will lie among the gathered values (parts in order, each its sent_ order).
    std::unordered_map<std::int64_t, std::map<std::int64_t, std::pair<Vec3, std::size_t>>> samples;
    std::size_t base = 0;
    for (const auto& part : allGather_(records)) {
        std::size_t at = 0, largest = 0;
        while (at < part.size()) {
            const auto record = take<SampleRecord>(part, at);
            const auto index = static_cast<std::size_t>(take<std::int64_t>(part, at));
            samples[record.point].emplace(record.key, std::pair{record.position, base + index});
            largest = std::max(largest, index + 1);
        }
        base += largest;
    }
    offsets_.push_back(0);
    for (const auto& [p, list] : around) {
        const auto& merged = samples.at(addressing.points[static_cast<std::size_t>(p)]);
        std::vector<Vec3> positions;
        for (const auto& [key, sample] : merged) {
            positions.push_back(sample.first);
            gathered_.push_back(sample.second);
        }
        bool rankDeficient = false;
        const auto alphas = pointFitWeights(mesh.points[p], positions, rankDeficient);
        weights_.insert(weights_.end(), alphas.begin(), alphas.end());
        points_.push_back(p);
        offsets_.push_back(static_cast<int>(weights_.size()));
    }
}

template <typename T>
void SharedPointWeights::apply(const FoamVolField<T>& field, std::vector<T>& pointValues) const {
    std::vector<std::byte> values;
    for (const int s : sent_) {
        if (s < mesh_.cellCount) {
            put(values, field.cells[s]);
            continue;
        }
        const int face = s - mesh_.cellCount;
        const int patch = mesh_.facePatch[face];
        const auto& patchValues = field.patchValues[patch];
        put(values, patchValues.empty() ? field.cells[mesh_.owner[face]]
                                        : patchValues[face - mesh_.patches[patch].start]);
    }
    std::vector<T> gathered;
    for (const auto& part : allGather_(values)) {
        std::size_t at = 0;
        while (at < part.size()) gathered.push_back(take<T>(part, at));
    }
    for (std::size_t i = 0; i < points_.size(); ++i) {
        T sum = T(0.0 * field.cells[0]);
        for (int k = offsets_[i]; k < offsets_[i + 1]; ++k)
            sum += weights_[static_cast<std::size_t>(k)] * gathered[gathered_[k]];
        pointValues[static_cast<std::size_t>(points_[i])] = sum;
    }
}

template void SharedPointWeights::apply(const FoamVolField<double>&, std::vector<double>&) const;
template void SharedPointWeights::apply(const FoamVolField<Vec3>&, std::vector<Vec3>&) const;
template void SharedPointWeights::apply(const FoamVolField<GasValues>&,
                                        std::vector<GasValues>&) const;

} // namespace slides
