// CellGrid: the broad phase — points binned into cubic cells, so that only points in the same
// or neighbouring cells are compared.
//
// Reference: Algorithm 4 and Eq. 4.36 of the reference (binning by counting sort, O(N_p)
// contact search). The cells of the points' bounding box, with an empty margin across y and z,
// are numbered x-slowest, z-fastest; the points are sorted by that number with a counting sort
// per 11-bit digit (least significant first, so stable), and only the occupied cells are kept,
// in that order. Memory is O(N) however long and thin the spray. A cell's forward neighbours
// are its successor (z + 1) and four rows of three consecutive numbers; since the rows' numbers
// grow with the cell's, one pointer per row walks the occupied cells alongside (a merge), so the
// search reads memory in order, without hashing.
#pragma once

#include "slides/core/box.h"
#include "slides/core/parallel.h"
#include "slides/core/vector.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace slides {

class CellGrid {
public:
    /// Bins the points into cubes of edge cellSize [m] (O(N)). Throws std::domain_error for a
    /// point that is not finite or a box of more cells than a 64-bit number can count.
    void build(const std::vector<Vec3>& points, double cellSize);

    /// build of the points inside `within` only: a point outside it (or not finite) is left
    /// out, as one that has left the domain and leaves the cloud at the step's end. size()
    /// counts the points kept; pointAt still gives their indices in points.
    void build(const std::vector<Vec3>& points, double cellSize, const Box& within);

    std::size_t size() const { return sorted_.size(); }
    double cellSize() const { return cellSize_; }

    /// Occupied cells of the grid, for splitting forEachPairInCells among threads.
    std::size_t occupiedCellCount() const { return cellStart_.empty() ? 0 : cellStart_.size() - 1; }
    /// The first slot of occupied cell c (c = occupiedCellCount(): one past the last slot).
    std::uint32_t firstSlotOf(std::size_t cell) const { return cellStart_[cell]; }

    /// The point in slot s of the cell order (slots of one cell are consecutive), and where it
    /// is: the points gathered in that order, so that a search over slots reads memory in order.
    std::uint32_t pointAt(std::size_t slot) const { return sorted_[slot]; }
    const Vec3& positionAt(std::size_t slot) const { return sortedPositions_[slot]; }

    /// Calls visit(i, j) for every pair of points in the same cell or in neighbouring cells
    /// whose first cell is among occupied cells [first, last): over all of them, each pair of
    /// points closer than one cell edge exactly once (13 of the 26 neighbours a cell, one of
    /// each opposite pair).
    template <typename Visit>
    void forEachPairInCells(std::size_t first, std::size_t last, Visit visit) const {
        forEachSlotPairInCells(
            first, last, [&](std::uint32_t a, std::uint32_t b) { visit(sorted_[a], sorted_[b]); });
    }

    /// forEachPairInCells by slots: visit(s, t) for the points in slots s and t.
    template <typename Visit>
    void forEachSlotPairInCells(std::size_t first, std::size_t last, Visit visit) const {
        if (first >= last) return;
        // The rows (dx, dy) = (0, 1), (1, −1), (1, 0), (1, 1), each of dz = −1, 0, 1.
        const std::array<Key, 4> rowOffset{yStride_, xStride_ - yStride_, xStride_,
                                           xStride_ + yStride_};
        std::array<std::size_t, 4> next{};
        for (std::size_t row = 0; row < 4; ++row)
            next[row] = firstCellFrom(cellKey_[first] + rowOffset[row] - 1);
        for (std::size_t cell = first; cell < last; ++cell) {
            const std::uint32_t begin = cellStart_[cell], end = cellStart_[cell + 1];
            const auto visitWith = [&](std::size_t other) {
                for (std::uint32_t a = begin; a < end; ++a)
                    for (std::uint32_t b = cellStart_[other]; b < cellStart_[other + 1]; ++b)
                        visit(a, b);
            };
            for (std::uint32_t a = begin; a < end; ++a)
                for (std::uint32_t b = a + 1; b < end; ++b) visit(a, b);
            const Key key = cellKey_[cell];
            if (cellKey_[cell + 1] == key + 1) visitWith(cell + 1); // the sentinel never matches
            for (std::size_t row = 0; row < 4; ++row) {
                const Key lowest = key + rowOffset[row] - 1;
                std::size_t& other = next[row];
                while (cellKey_[other] < lowest) ++other;
                for (std::size_t k = other; cellKey_[k] <= lowest + 2; ++k) visitWith(k);
            }
        }
    }

    /// Calls visit(j) for every point j within the cells that a ball of radius reach around
    /// centre can touch (a superset of the points closer than reach).
    template <typename Visit>
    void forEachPointWithin(const Vec3& centre, double reach, Visit visit) const {
        if (sorted_.empty()) return;
        const auto range = static_cast<std::int64_t>(std::ceil(reach / cellSize_));
        const Vec3 offset = (centre - origin_) / cellSize_;
        std::array<std::int64_t, 3> low{}, high{};
        for (int axis = 0; axis < 3; ++axis) {
            // Clamped to the box in double first: a far centre must not overflow an integer.
            const double cell = std::floor(offset[axis]) + (axis == 0 ? 0 : 1);
            const auto last = static_cast<double>(cellsPerAxis_[axis] - 1);
            low[axis] = static_cast<std::int64_t>(std::clamp(cell - range, 0.0, last + 1));
            high[axis] = static_cast<std::int64_t>(std::clamp(cell + range, -1.0, last));
        }
        for (std::int64_t x = low[0]; x <= high[0]; ++x)
            for (std::int64_t y = low[1]; y <= high[1]; ++y) {
                if (low[2] > high[2]) return;
                const Key row = static_cast<Key>(x) * xStride_ + static_cast<Key>(y) * yStride_;
                for (std::size_t k = firstCellFrom(row + static_cast<Key>(low[2]));
                     cellKey_[k] <= row + static_cast<Key>(high[2]); ++k)
                    for (std::uint32_t slot = cellStart_[k]; slot < cellStart_[k + 1]; ++slot)
                        visit(sorted_[slot]);
            }
    }

private:
    using Key = std::uint64_t;

    /// build of the points for which keep(point) holds.
    template <typename Keep>
    void buildOf(const std::vector<Vec3>& points, double cellSize, Keep keep);

    /// Sorts keyed_ by key, each below keys.
    void sortByKey(Key keys);

    /// The first occupied cell whose number is at least key (the sentinel if none).
    std::size_t firstCellFrom(Key key) const {
        return static_cast<std::size_t>(
            std::lower_bound(cellKey_.begin(), cellKey_.end() - 1, key) - cellKey_.begin());
    }

    /// A point's number and index, as the sort moves them.
    struct Keyed {
        Key key;
        std::uint32_t point;
    };

    double cellSize_ = 1;
    Vec3 origin_ = Vec3::Zero();                 ///< the corner of the box's first cell
    std::array<std::int64_t, 3> cellsPerAxis_{}; ///< with the margins across y and z
    Key yStride_ = 1, xStride_ = 1;              ///< a cell's number is x·xStride + y·yStride + z
    std::vector<Key> cellKey_;              ///< occupied cells' numbers ascending, then a sentinel
    std::vector<std::uint32_t> cellStart_;  ///< cell c holds sorted_[start[c], start[c+1])
    std::vector<std::uint32_t> sorted_;     ///< point indices ordered by cell
    std::vector<Vec3> sortedPositions_;     ///< the points in that order
    std::vector<Keyed> keyed_, spare_;      ///< scratch of build
    std::vector<std::uint32_t> digitCount_; ///< scratch of build
};

/// What test(s, t) finds for every pair of slots the grid offers (forEachSlotPairInCells; the
/// points are grid.pointAt(s), pointAt(t)), the pairs for which it returns a value, and after
/// each block of cells' pairs what single(s, found) appends for each slot s of those cells:
/// searched in parallel over blocks of cells and joined in cell order, so the list is the same
/// for any number of threads, and a thread's share of it is a share of space.
template <typename Found, typename Test, typename Single>
std::vector<Found> collectPairsAndSingles(const CellGrid& grid, Test test, Single single) {
    const auto cells = static_cast<std::ptrdiff_t>(grid.occupiedCellCount());
    constexpr std::ptrdiff_t chunk = 4096; // cells
    return collectInOrder<Found>(
        (cells + chunk - 1) / chunk,
        [&](std::ptrdiff_t block, std::vector<Found>& found) {
            const std::ptrdiff_t first = block * chunk;
            const auto last = static_cast<std::size_t>(std::min(first + chunk, cells));
            grid.forEachSlotPairInCells(static_cast<std::size_t>(first), last,
                                        [&](std::uint32_t a, std::uint32_t b) {
                                            if (auto pair = test(a, b)) found.push_back(*pair);
                                        });
            for (std::uint32_t slot = grid.firstSlotOf(static_cast<std::size_t>(first));
                 slot < grid.firstSlotOf(last); ++slot)
                single(slot, found);
        },
        2);
}

/// collectPairsAndSingles without singles.
template <typename Found, typename Test>
std::vector<Found> collectPairs(const CellGrid& grid, Test test) {
    return collectPairsAndSingles<Found>(grid, test, [](std::uint32_t, std::vector<Found>&) {});
}

} // namespace slides
