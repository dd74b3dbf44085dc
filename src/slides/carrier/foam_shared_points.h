// SharedPointWeights: the cellPoint values of the points a part of a decomposed case shares
// with other parts, fitted over the samples of every part as the whole mesh's fit takes them.
//
// Reference: carrier/foam_interpolation.h (the point fit); OpenFOAM v1912 decomposePar's
// constant/polyMesh/{point,cell,face}ProcAddressing (each part's point, cell and face → the
// whole mesh's). A point on a processor patch sees only some of its cells in one part; here
// every part sends the samples it holds of such points (whole-mesh id, position, value), and
// each part fits them in the whole mesh's sample order (cells, then boundary faces, by id), so
// the point's value is the serial run's up to the round-off of cell centres summed over faces
// in another order. The rank-deficient widening to the next cells stays within the part.
//
//     SharedPointWeights shared(mesh, readPartAddressing(processorDirectory, mesh), allGather);
//     shared.apply(field, pointValues);
#pragma once

#include "slides/carrier/foam_field.h"

#include <cstddef>
#include <filesystem>
#include <functional>
#include <span>
#include <vector>

namespace slides {

/// Every part's bytes, by part (a collective operation over the parts).
using PartAllGather =
    std::function<std::vector<std::vector<std::byte>>(std::span<const std::byte>)>;

/// A part's labels in the whole mesh.
struct PartAddressing {
    std::vector<std::int64_t> points; ///< pointProcAddressing
    std::vector<std::int64_t> cells;  ///< cellProcAddressing
    std::vector<std::int64_t> faces;  ///< faceProcAddressing: ±(whole face + 1), − when flipped
};

/// Reads PART/constant/polyMesh/{point,cell,face}ProcAddressing of the part's mesh; InputError
/// naming the file when one does not fit it.
PartAddressing readPartAddressing(const std::filesystem::path& partDirectory, const FoamMesh& mesh);

class SharedPointWeights {
public:
    /// Collective: every part constructs its own at the same time (addressing read and checked
    /// before, so that no part fails on its own in between).
    SharedPointWeights(const FoamMesh& mesh, const PartAddressing& addressing,
                       PartAllGather allGather);

    /// pointValues (field's, by carrier/foam_interpolation.h) with the shared points' values
    /// fitted over every part's samples. Collective.
    template <typename T>
    void apply(const FoamVolField<T>& field, std::vector<T>& pointValues) const;

private:
    const FoamMesh& mesh_;
    PartAllGather allGather_;
    std::vector<int> sent_;             ///< this part's samples of shared points, in the order sent
    std::vector<int> points_;           ///< the shared points (local index)
    std::vector<int> offsets_;          ///< samples of points_[i]: [offsets_[i], offsets_[i + 1])
    std::vector<std::size_t> gathered_; ///< each sample's index in the gathered values
    std::vector<double> weights_;
};

} // namespace slides
