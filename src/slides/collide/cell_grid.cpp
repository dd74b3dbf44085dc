#include "slides/collide/cell_grid.h"

#include <limits>
#include <stdexcept>
#include <string>

namespace slides {

template <typename Keep>
void CellGrid::buildOf(const std::vector<Vec3>& points, double cellSize, Keep keep) {
    cellSize_ = cellSize;
    keyed_.clear();
    Vec3 lowest = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 highest = -lowest;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!keep(points[i])) continue;
        keyed_.push_back({0, static_cast<std::uint32_t>(i)});
        lowest = lowest.cwiseMin(points[i]);
        highest = highest.cwiseMax(points[i]);
    }
    const std::size_t count = keyed_.size();
    origin_ = count == 0 ? Vec3::Zero() : lowest;
    // The box's cells, with one empty layer on either side across y and z: the rows of a
    // cell's neighbours then never run past the box's edge into the next row.
    double boxCells = 1;
    for (int axis = 0; axis < 3; ++axis) {
        const double span =
            count == 0 ? 1 : std::floor((highest[axis] - lowest[axis]) / cellSize) + 1;
        const double cells = span + (axis == 0 ? 0 : 2);
        boxCells *= cells;
        if (!(boxCells < 0x1p62))
            throw std::domain_error("collision grid: the particles span more than 2^62 cells of " +
                                    std::to_string(cellSize) + " m; bound the domain");
        cellsPerAxis_[axis] = static_cast<std::int64_t>(cells);
    }
    yStride_ = static_cast<Key>(cellsPerAxis_[2]);
    xStride_ = yStride_ * static_cast<Key>(cellsPerAxis_[1]);

    for (Keyed& entry : keyed_) {
        const Vec3 offset = (points[entry.point] - origin_) / cellSize;
        const auto cell = [&](int axis) { return static_cast<Key>(std::floor(offset[axis])); };
        entry.key = cell(0) * xStride_ + (cell(1) + 1) * yStride_ + cell(2) + 1;
    }
    sortByKey(static_cast<Key>(boxCells));

    sorted_.resize(count);
    sortedPositions_.resize(count);
    cellKey_.clear();
    cellStart_.clear();
    for (std::size_t slot = 0; slot < count; ++slot) {
        sorted_[slot] = keyed_[slot].point;
        sortedPositions_[slot] = points[keyed_[slot].point];
        if (slot == 0 || keyed_[slot].key != keyed_[slot - 1].key) {
            cellKey_.push_back(keyed_[slot].key);
            cellStart_.push_back(static_cast<std::uint32_t>(slot));
        }
    }
    cellKey_.push_back(std::numeric_limits<Key>::max());
    cellStart_.push_back(static_cast<std::uint32_t>(count));
}

void CellGrid::build(const std::vector<Vec3>& points, double cellSize) {
    buildOf(points, cellSize, [](const Vec3& point) {
        if (!point.allFinite())
            throw std::domain_error("collision grid: a particle's position is not finite");
        return true;
    });
}

void CellGrid::build(const std::vector<Vec3>& points, double cellSize, const Box& within) {
    buildOf(points, cellSize, [&](const Vec3& point) { return insideBox(within, point); });
}

void CellGrid::sortByKey(Key keys) {
    // Least significant digit first, each a stable counting sort (Algorithm 4): the digits
    // split the key's bits evenly, at most 11 bits each.
    int bits = 0;
    while (bits < 64 && (keys - 1) >> bits != 0) ++bits;
    const int passes = (bits + 10) / 11;
    const int width = passes == 0 ? 0 : (bits + passes - 1) / passes;
    const std::size_t digits = std::size_t{1} << width;
    spare_.resize(keyed_.size());
    for (int pass = 0; pass < passes; ++pass) {
        const int shift = pass * width;
        digitCount_.assign(digits + 1, 0);
        for (const Keyed& entry : keyed_) ++digitCount_[((entry.key >> shift) & (digits - 1)) + 1];
        for (std::size_t d = 1; d <= digits; ++d) digitCount_[d] += digitCount_[d - 1];
        for (const Keyed& entry : keyed_)
            spare_[digitCount_[(entry.key >> shift) & (digits - 1)]++] = entry;
        keyed_.swap(spare_);
    }
}

} // namespace slides
