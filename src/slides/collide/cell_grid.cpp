#include "slides/collide/cell_grid.h"

#include <algorithm>

namespace slides {

CellGrid::Cell CellGrid::cellOf(const Vec3& point) const {
    return {static_cast<std::int64_t>(std::floor(point.x() / cellSize_)),
            static_cast<std::int64_t>(std::floor(point.y() / cellSize_)),
            static_cast<std::int64_t>(std::floor(point.z() / cellSize_))};
}

const std::array<std::array<std::int64_t, 3>, 13>& CellGrid::forwardOffsets() {
    static const auto offsets = [] {
        std::array<std::array<std::int64_t, 3>, 13> forward{};
        std::size_t n = 0;
        for (std::int64_t dx = -1; dx <= 1; ++dx)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
                for (std::int64_t dz = -1; dz <= 1; ++dz)
                    if (std::array<std::int64_t, 3>{dx, dy, dz} >
                        std::array<std::int64_t, 3>{0, 0, 0})
                        forward[n++] = {dx, dy, dz};
        return forward;
    }();
    return offsets;
}

std::size_t CellGrid::bucketOf(const Cell& cell) const {
    if (dense_) {
        std::int64_t index = 0;
        for (int axis = 2; axis >= 0; --axis) {
            const std::int64_t offset = cell[axis] - lowestCell_[axis];
            // Outside the box: the last bucket, which holds no point.
            if (offset < 0 || offset >= cellsPerAxis_[axis]) return bucketStart_.size() - 2;
            index = index * cellsPerAxis_[axis] + offset;
        }
        return static_cast<std::size_t>(index);
    }
    // The primes of Teschner et al. (2003), then a multiplicative mix of the high bits.
    const auto key = static_cast<std::uint64_t>(cell[0]) * 73856093u ^
                     static_cast<std::uint64_t>(cell[1]) * 19349663u ^
                     static_cast<std::uint64_t>(cell[2]) * 83492791u;
    const std::uint64_t mixed = (key ^ (key >> 29)) * 0xbf58476d1ce4e5b9ull;
    return static_cast<std::size_t>((mixed ^ (mixed >> 32)) % (bucketStart_.size() - 1));
}

void CellGrid::build(const std::vector<Vec3>& points, double cellSize) {
    cellSize_ = cellSize;
    const std::size_t count = points.size();
    cells_.resize(count);
    Cell lowest{}, highest{};
    for (std::size_t i = 0; i < count; ++i) {
        cells_[i] = cellOf(points[i]);
        for (int axis = 0; axis < 3; ++axis) {
            lowest[axis] = i == 0 ? cells_[i][axis] : std::min(lowest[axis], cells_[i][axis]);
            highest[axis] = i == 0 ? cells_[i][axis] : std::max(highest[axis], cells_[i][axis]);
        }
    }
    // Dense when the box's cells are few per point (checked axis by axis against overflow).
    const double limit = static_cast<double>(denseCellsPerPoint) * static_cast<double>(count) + 64;
    double boxCells = 1;
    for (int axis = 0; axis < 3; ++axis) {
        cellsPerAxis_[axis] = highest[axis] - lowest[axis] + 1;
        boxCells *= static_cast<double>(cellsPerAxis_[axis]);
    }
    dense_ = boxCells <= limit;
    lowestCell_ = lowest;
    // Dense: a bucket per box cell and an empty one for cells outside; hashed: 2N + 1.
    const std::size_t buckets = dense_ ? static_cast<std::size_t>(boxCells) + 1 : 2 * count + 1;
    bucketStart_.assign(buckets + 1, 0);
    sorted_.resize(count);
    sortedCells_.resize(count);
    auto& bucket = bucketOfPoint_;
    bucket.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        bucket[i] = bucketOf(cells_[i]);
        ++bucketStart_[bucket[i] + 1];
    }
    for (std::size_t b = 1; b < bucketStart_.size(); ++b) bucketStart_[b] += bucketStart_[b - 1];
    auto& next = nextSlot_;
    next.assign(bucketStart_.begin(), bucketStart_.end() - 1);
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint32_t slot = next[bucket[i]]++;
        sorted_[slot] = static_cast<std::uint32_t>(i);
        sortedCells_[slot] = cells_[i];
    }
}

} // namespace slides
