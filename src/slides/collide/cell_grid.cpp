#include "slides/collide/cell_grid.h"

namespace slides {

CellGrid::Cell CellGrid::cellOf(const Vec3& point) const {
    return {static_cast<std::int64_t>(std::floor(point.x() / cellSize_)),
            static_cast<std::int64_t>(std::floor(point.y() / cellSize_)),
            static_cast<std::int64_t>(std::floor(point.z() / cellSize_))};
}

std::size_t CellGrid::bucketOf(const Cell& cell) const {
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
    bucketStart_.assign(2 * count + 2, 0);
    cells_.resize(count);
    sorted_.resize(count);
    auto& bucket = bucketOfPoint_;
    bucket.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        cells_[i] = cellOf(points[i]);
        bucket[i] = bucketOf(cells_[i]);
        ++bucketStart_[bucket[i] + 1];
    }
    for (std::size_t b = 1; b < bucketStart_.size(); ++b) bucketStart_[b] += bucketStart_[b - 1];
    auto& next = nextSlot_;
    next.assign(bucketStart_.begin(), bucketStart_.end() - 1);
    for (std::size_t i = 0; i < count; ++i)
        sorted_[next[bucket[i]]++] = static_cast<std::uint32_t>(i);
}

} // namespace slides
