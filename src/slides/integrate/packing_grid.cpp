#include "slides/integrate/packing_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace slides {

PackingGrid::PackingGrid(const PackingRegion& region, double reach)
    : lower_(region.boundsLower()), periodic_(region.periodic) {
    const Vec3 extent = region.boundsUpper() - lower_;
    double cellCount = 1;
    for (int a = 0; a < 3; ++a) {
        // At most 2^20 cells an axis and 2^28 in all: a region far larger than its spheres'
        // count needs is refused rather than allocated.
        cells_[a] = static_cast<int>(std::clamp(std::floor(extent[a] / reach), 1.0, 1048576.0));
        cellSize_[a] = extent[a] / cells_[a];
        cellCount *= cells_[a];
    }
    if (!(cellCount <= 268435456.0))
        throw std::length_error("a packing region of more than 2^28 cells of its spheres' size");
    head_.assign(static_cast<std::size_t>(cellCount), -1);
}

void PackingGrid::clear() {
    std::fill(head_.begin(), head_.end(), -1);
    next_.clear();
}

void PackingGrid::insert(std::uint32_t i, const Vec3& centre) {
    if (next_.size() <= i) next_.resize(i + 1, -1);
    const std::array<int, 3> cell = cellOf(centre);
    std::int32_t& first = head_[index(cell[0], cell[1], cell[2])];
    next_[i] = first;
    first = static_cast<std::int32_t>(i);
}

void PackingGrid::rebuild(const std::vector<Vec3>& centres) {
    clear();
    next_.resize(centres.size(), -1);
    for (std::size_t i = 0; i < centres.size(); ++i)
        insert(static_cast<std::uint32_t>(i), centres[i]);
}

std::array<int, 3> PackingGrid::cellOf(const Vec3& point) const {
    std::array<int, 3> cell{};
    for (int a = 0; a < 3; ++a)
        cell[a] = std::clamp(static_cast<int>(std::floor((point[a] - lower_[a]) / cellSize_[a])), 0,
                             cells_[a] - 1);
    return cell;
}

int PackingGrid::neighbourCells(int c, int a, std::array<int, 3>& out) const {
    const int n = cells_[a];
    int count = 0;
    for (int d = -1; d <= 1; ++d) {
        int neighbour = c + d;
        if (periodic_)
            neighbour = (neighbour + n) % n;
        else if (neighbour < 0 || neighbour >= n)
            continue;
        if (std::find(out.begin(), out.begin() + count, neighbour) == out.begin() + count)
            out[static_cast<std::size_t>(count++)] = neighbour;
    }
    return count;
}

} // namespace slides
