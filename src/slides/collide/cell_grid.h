// CellGrid: the broad phase — points binned into cubic cells by a counting sort over their
// cells' buckets, so that only points in the same or nearby cells are compared.
//
// Reference: Algorithm 4 and Eq. 4.36 of the reference (binning, O(N_p) contact search).
// A compact cloud (a bounding box of at most denseCellsPerPoint cells a point) gets one bucket
// per cell of that box, in x-fastest order, so that neighbouring cells lie near in memory. A long
// thin spray gets hashed buckets instead (Teschner et al. 2003, "Optimized spatial hashing for
// collision detection of deformable objects"), twice the number of points: memory stays O(N)
// however long the spray, at the price of a cache miss per neighbour cell. A bucket shared by
// two cells only costs a comparison of cell coordinates.
#pragma once

#include "slides/core/vector.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace slides {

class CellGrid {
public:
    using Cell = std::array<std::int64_t, 3>;

    /// Bins the points into cubes of edge cellSize [m] (O(N), counting sort).
    void build(const std::vector<Vec3>& points, double cellSize);

    std::size_t size() const { return cells_.size(); }
    double cellSize() const { return cellSize_; }
    /// Whether the last build chose one bucket per cell of the bounding box (else hashed).
    bool dense() const { return dense_; }

    /// The most cells a point a dense grid may spend.
    static constexpr std::int64_t denseCellsPerPoint = 8;

    /// Buckets of the grid, for splitting forEachPairInBuckets among threads.
    std::size_t bucketCount() const { return bucketStart_.size() - 1; }

    /// Calls visit(i, j) for every pair of points in the same cell or in neighbouring cells
    /// whose first cell lies in buckets [first, last): over all buckets, each pair of points
    /// closer than one cell edge exactly once. Neighbour cells are looked up once per occupied
    /// cell (13 of the 26, one of each opposite pair), not once per point.
    template <typename Visit>
    void forEachPairInBuckets(std::size_t first, std::size_t last, Visit visit) const {
        for (std::size_t bucket = first; bucket < last; ++bucket) {
            const std::uint32_t begin = bucketStart_[bucket], end = bucketStart_[bucket + 1];
            for (std::uint32_t k = begin; k < end; ++k) {
                const Cell& cell = sortedCells_[k];
                if (!firstOfItsCell(k, begin)) continue; // a cell sharing the bucket, done
                for (std::uint32_t a = k; a < end; ++a) {
                    if (!sameCell(sortedCells_[a], cell)) continue;
                    for (std::uint32_t b = a + 1; b < end; ++b)
                        if (sameCell(sortedCells_[b], cell)) visit(sorted_[a], sorted_[b]);
                }
                for (const auto& offset : forwardOffsets()) {
                    const Cell next{cell[0] + offset[0], cell[1] + offset[1], cell[2] + offset[2]};
                    forEachPointIn(next, [&](std::uint32_t j) {
                        for (std::uint32_t a = k; a < end; ++a)
                            if (sameCell(sortedCells_[a], cell)) visit(sorted_[a], j);
                    });
                }
            }
        }
    }

    /// Calls visit(j) for every point j within the cells that a ball of radius reach around
    /// centre can touch (a superset of the points closer than reach).
    template <typename Visit>
    void forEachPointWithin(const Vec3& centre, double reach, Visit visit) const {
        if (cells_.empty()) return;
        const auto range = static_cast<std::int64_t>(std::ceil(reach / cellSize_));
        forEachPointNear(cellOf(centre), range, visit);
    }

private:
    Cell cellOf(const Vec3& point) const;
    std::size_t bucketOf(const Cell& cell) const;

    static bool sameCell(const Cell& a, const Cell& b) {
        return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
    }

    /// Whether slot k holds the first point of its cell within the bucket starting at begin.
    bool firstOfItsCell(std::uint32_t k, std::uint32_t begin) const {
        for (std::uint32_t earlier = begin; earlier < k; ++earlier)
            if (sameCell(sortedCells_[earlier], sortedCells_[k])) return false;
        return true;
    }

    /// The 13 neighbour offsets that come after (0, 0, 0) in lexicographic order.
    static const std::array<std::array<std::int64_t, 3>, 13>& forwardOffsets();

    template <typename Visit> void forEachPointIn(const Cell& cell, Visit visit) const {
        const std::size_t bucket = bucketOf(cell);
        for (std::uint32_t k = bucketStart_[bucket]; k < bucketStart_[bucket + 1]; ++k) {
            if (sameCell(sortedCells_[k], cell)) visit(sorted_[k]); // buckets can share cells
        }
    }

    template <typename Visit>
    void forEachPointNear(const Cell& centre, std::int64_t range, Visit visit) const {
        for (std::int64_t dx = -range; dx <= range; ++dx)
            for (std::int64_t dy = -range; dy <= range; ++dy)
                for (std::int64_t dz = -range; dz <= range; ++dz)
                    forEachPointIn({centre[0] + dx, centre[1] + dy, centre[2] + dz}, visit);
    }

    double cellSize_ = 1;
    bool dense_ = false;
    Cell lowestCell_{};                      ///< dense: the bounding box's first cell
    Cell cellsPerAxis_{};                    ///< dense: the box's cells per axis
    std::vector<Cell> cells_;                ///< each point's cell
    std::vector<std::uint32_t> bucketStart_; ///< bucket b holds sorted_[start[b], start[b+1])
    std::vector<std::uint32_t> sorted_;      ///< point indices ordered by bucket
    std::vector<Cell> sortedCells_;          ///< their cells, beside them for locality
    std::vector<std::size_t> bucketOfPoint_; ///< scratch of build
    std::vector<std::uint32_t> nextSlot_;    ///< scratch of build
};

/// What test(a, b) finds for every pair of points the grid offers (forEachPairInBuckets), the
/// pairs for which it returns a value: searched in parallel over blocks of buckets and joined in
/// bucket order, so the list is the same for any number of threads.
template <typename Found, typename Test>
std::vector<Found> collectPairs(const CellGrid& grid, Test test) {
    const auto buckets = static_cast<std::ptrdiff_t>(grid.bucketCount());
    constexpr std::ptrdiff_t chunk = 4096;
    std::vector<std::vector<Found>> perThread;
#pragma omp parallel
    {
#ifdef _OPENMP
#pragma omp single
        perThread.resize(static_cast<std::size_t>(omp_get_num_threads()));
        auto& found = perThread[static_cast<std::size_t>(omp_get_thread_num())];
#else
        perThread.resize(1);
        auto& found = perThread[0];
#endif
        // Static blocks in thread order: joining the threads' lists keeps the bucket order.
#pragma omp for schedule(static)
        for (std::ptrdiff_t first = 0; first < buckets; first += chunk) {
            const auto last = static_cast<std::size_t>(std::min(first + chunk, buckets));
            grid.forEachPairInBuckets(static_cast<std::size_t>(first), last,
                                      [&](std::uint32_t a, std::uint32_t b) {
                                          if (auto pair = test(a, b)) found.push_back(*pair);
                                      });
        }
    }
    std::vector<Found> all;
    for (const auto& found : perThread) all.insert(all.end(), found.begin(), found.end());
    return all;
}

} // namespace slides
