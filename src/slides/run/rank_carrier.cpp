#include "slides/run/rank_carrier.h"

#include "slides/carrier/foam_decomposition.h"
#include "slides/carrier/foam_field.h"
#include "slides/core/error.h"
#include "slides/core/name_table.h"
#include "slides/run/rank_agreement.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstring>

namespace slides {

namespace {

template <typename T> Bytes bytesOf(const std::vector<T>& values) {
    Bytes bytes(values.size() * sizeof(T));
    if (!values.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
    return bytes;
}

template <typename T> void append(std::vector<T>& values, const Bytes& bytes) {
    const std::size_t start = values.size();
    values.resize(start + bytes.size() / sizeof(T));
    if (!bytes.empty())
        std::memcpy(static_cast<void*>(values.data() + start), bytes.data(), bytes.size());
}

/// The doubles of one sample: U, then ∇U, k and ε, T, ∂U/∂t where asked, then the resolution
/// length.
std::size_t sampleWidth(CarrierNeeds needs) {
    return 3 + (needs.velocityGradient ? 9 : 0) + (needs.turbulence ? 2 : 0) +
           (needs.temperature ? 1 : 0) + (needs.timeDerivative ? 3 : 0) + 1;
}

} // namespace

RankCarrier::RankCarrier(const std::filesystem::path& caseDirectory,
                         const FoamCarrierSettings& settings, const RankCommunicator& ranks)
    : caseDirectory_(caseDirectory), ranks_(ranks) {
    PartAddressing addressing;
    agreeOnFailure(ranks, [&] {
        requireDecompositionFits(caseDirectory, true, ranks.size());
        const auto dictionary = (caseDirectory / "constant" / "slidesProperties").string();
        if (settings.interpolation == FoamInterpolation::lattice)
            throw InputError(dictionary, 0, "carrier.foamFieldCoeffs.interpolation",
                             "the lattice scheme is not supported in parallel runs yet: use "
                             "cellPoint or cell");
        part_ = std::make_unique<FoamCarrier>(foamProcessorDirectory(caseDirectory, ranks.rank()),
                                              settings);
        addressing =
            readPartAddressing(foamProcessorDirectory(caseDirectory, ranks.rank()), part_->mesh());
        const auto& patches = part_->mesh().patches;
        for (const FoamPatch& patch : patches) {
            if (patch.type != PatchType::processor) {
                if (boundaryNames_.size() != static_cast<std::size_t>(&patch - patches.data()))
                    throw InputError((foamProcessorDirectory(caseDirectory, ranks.rank()) /
                                      "constant" / "polyMesh" / "boundary")
                                         .string(),
                                     0, patch.name, "a patch of the case after a processor patch");
                boundaryNames_.push_back(patch.name);
            }
        }
    });
    part_->shareProcessorPoints(
        addressing, [&](std::span<const std::byte> bytes) { return ranks_.allGather(bytes); });
    // The parts' boxes (a wedge part's swept about the axis) bound the whole mesh's.
    std::array<double, 3> low{}, high{};
    const FoamMesh& mesh = part_->mesh();
    const Box part = *part_->bounds();
    for (int axis = 0; axis < 3; ++axis) {
        low[axis] = part.min[axis];
        high[axis] = part.max[axis];
    }
    ranks_.min(low);
    ranks_.max(high);
    bounds_ = {Vec3(low[0], low[1], low[2]), Vec3(high[0], high[1], high[2])};
    const std::uint64_t cells = ranks_.sum(static_cast<std::uint64_t>(mesh.cellCount));
    const auto time = foamTimeDirectory(foamProcessorDirectory(caseDirectory, 0), settings.time);
    description_ = "foamField " + (caseDirectory / "processor*" / time.filename()).string() + " (" +
                   std::to_string(cells) + " cells in " + std::to_string(ranks_.size()) +
                   " processor parts, " +
                   std::string(nameOf(foamInterpolationNames(), settings.interpolation)) + ")";
}

void RankCarrier::sample(std::span<const Vec3> points, double time, CarrierNeeds needs,
                         CarrierSample& out) const {
    std::vector<std::int32_t> locations(points.size(), -1);
    sampleFrom(points, locations, time, needs, out);
}

void RankCarrier::sampleFrom(std::span<const Vec3> points, std::span<std::int32_t> locations,
                             double time, CarrierNeeds needs, CarrierSample& out) const {
    part_->sampleFrom(points, locations, time, needs, out);
    std::vector<Vec3> away; // the points this part does not hold
    std::vector<std::size_t> awayIndex;
    for (std::size_t i = 0; i < points.size(); ++i)
        if (locations[i] < -1) {
            away.push_back(points[i]);
            awayIndex.push_back(i);
        }
    const auto gathered = ranks_.allGather(bytesOf(away));
    std::vector<Vec3> asked;
    std::size_t offset = 0; // of this rank's points in asked
    for (int r = 0; r < ranks_.size(); ++r) {
        if (r == ranks_.rank()) offset = asked.size();
        append(asked, gathered[r]);
    }
    if (asked.empty()) return;
    std::vector<std::int32_t> found(asked.size(), -1);
    CarrierSample here;
    part_->sampleFrom(asked, found, time, needs, here);
    // One record a point: the claim (this rank where it holds the point), then the values.
    const std::size_t width = 1 + sampleWidth(needs);
    std::vector<double> records(asked.size() * width, 0.0);
    for (std::size_t k = 0; k < asked.size(); ++k) {
        double* v = records.data() + k * width;
        if (found[k] < 0) {
            *v = INFINITY;
            continue;
        }
        *v++ = ranks_.rank();
        for (int d = 0; d < 3; ++d) *v++ = here.velocity[k][d];
        if (needs.velocityGradient)
            for (int d = 0; d < 9; ++d) *v++ = here.velocityGradient[k](d % 3, d / 3);
        if (needs.turbulence) {
            *v++ = here.turbulentKineticEnergy[k];
            *v++ = here.dissipationRate[k];
        }
        if (needs.temperature) *v++ = here.temperature[k];
        if (needs.timeDerivative)
            for (int d = 0; d < 3; ++d) *v++ = here.velocityTimeDerivative[k][d];
        *v = part_->resolutionLength(found[k]);
    }
    ranks_.keepLowestClaims(records, width); // the lowest rank holding a point answers it
    const std::int32_t remoteBase = part_->locator().tetIndexEnd();
    remoteResolution_.assign(away.size(), INFINITY);
    for (std::size_t j = 0; j < away.size(); ++j) {
        const std::size_t i = awayIndex[j], k = offset + j;
        const double* v = records.data() + k * width;
        if (!(*v++ < INFINITY)) { // outside the whole mesh: never through a processor patch
            if (locations[i] <= -3 && -3 - locations[i] >= firstProcessorPatch()) locations[i] = -2;
            continue;
        }
        for (int d = 0; d < 3; ++d) out.velocity[i][d] = *v++;
        if (needs.velocityGradient)
            for (int d = 0; d < 9; ++d) out.velocityGradient[i](d % 3, d / 3) = *v++;
        if (needs.turbulence) {
            out.turbulentKineticEnergy[i] = *v++;
            out.dissipationRate[i] = *v++;
        }
        if (needs.temperature) out.temperature[i] = *v++;
        if (needs.timeDerivative)
            for (int d = 0; d < 3; ++d) out.velocityTimeDerivative[i][d] = *v++;
        remoteResolution_[j] = *v;
        const bool indexable =
            static_cast<std::int64_t>(remoteBase) + static_cast<std::int64_t>(j) <
            static_cast<std::int64_t>(INT_MAX);
        locations[i] = indexable ? remoteBase + static_cast<std::int32_t>(j) : -1;
    }
}

double RankCarrier::resolutionLength(std::int32_t location) const {
    const std::int32_t remoteBase = part_->locator().tetIndexEnd();
    if (location >= remoteBase) {
        const auto j = static_cast<std::size_t>(location - remoteBase);
        return j < remoteResolution_.size() ? remoteResolution_[j] : INFINITY;
    }
    return part_->resolutionLength(location);
}

std::vector<PatchTriangle> RankCarrier::patchTriangles(const std::string& name) const {
    std::vector<PatchTriangle> triangles;
    const std::vector<PatchTriangle> mine =
        holdsPatch(name) ? part_->patchTriangles(name) : std::vector<PatchTriangle>{};
    for (const Bytes& part : ranks_.allGather(bytesOf(mine))) append(triangles, part);
    if (triangles.empty())
        throw InputError((caseDirectory_ / "processor*").string(), 0, "",
                         "patch '" + name + "' has no faces on any rank");
    return triangles;
}

std::vector<std::int32_t> RankCarrier::patchTriangleLocations(const std::string& name) const {
    // In patchTriangles' order: the ranks' triangles one after the other.
    const std::vector<std::int32_t> mine =
        holdsPatch(name) ? part_->patchTriangleLocations(name) : std::vector<std::int32_t>{};
    std::vector<std::int32_t> locations;
    const auto counts = ranks_.allGather(bytesOf(std::vector<std::uint64_t>{mine.size()}));
    for (int r = 0; r < ranks_.size(); ++r) {
        if (r == ranks_.rank()) {
            locations.insert(locations.end(), mine.begin(), mine.end());
            continue;
        }
        std::vector<std::uint64_t> count;
        append(count, counts[static_cast<std::size_t>(r)]);
        locations.resize(locations.size() + count.at(0), heldElsewhere);
    }
    return locations;
}

void RankCarrier::keepHeldHere(std::span<const Vec3> points, std::span<std::int32_t> locations,
                               std::vector<std::uint8_t>& keep) const {
    // Key (held here 0, else 1) × ranks + rank: the smallest over the ranks keeps the point.
    const int me = ranks_.rank(), size = ranks_.size();
    const FoamLocator& locator = part_->locator();
    std::vector<int> keys(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
        if (locations[k] == -1) {
            const TetLocation at = locator.locateFrom(part_->meshPoint(points[k]), -1);
            locations[k] = at.found() ? at.tet : heldElsewhere;
        }
        const bool held = locations[k] >= 0 && locations[k] < locator.tetIndexEnd();
        keys[k] = (held ? 0 : size) + me;
    }
    ranks_.min(keys);
    keep.resize(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
        keep[k] = keys[k] % size == me;
        if (keys[k] >= size) locations[k] = -1; // held by no rank
    }
}

bool RankCarrier::holdsPatch(const std::string& name) const {
    const auto& patches = part_->mesh().patches;
    return std::ranges::any_of(
        patches, [&](const FoamPatch& patch) { return patch.name == name && patch.size > 0; });
}

} // namespace slides
