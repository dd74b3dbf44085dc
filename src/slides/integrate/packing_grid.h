// PackingGrid: the spheres of a packing binned into cells of at least the largest contact
// distance, so that a test for overlap reads only the 27 cells around a point: O(1) per
// insertion attempt of random sequential addition, O(N) per sweep of the growth algorithm.
//
// Reference: Section 4.3 and the binning of Algorithm 4 (Eq. 4.36). Unlike collide/cell_grid.h
// (sorted once per step) a sphere is added at any time in O(1): one linked list per cell over
// the region's bounding box, whose cells wrap round across a periodic box's faces.
#pragma once

#include "slides/integrate/packing_region.h"

#include <array>
#include <cstdint>
#include <vector>

namespace slides {

class PackingGrid {
public:
    /// Cells over the region's bounding box, of edge at least reach [m] (the largest distance
    /// at which two centres can overlap).
    PackingGrid(const PackingRegion& region, double reach);

    /// Adds sphere i at centre (i counts up from 0, each once after clear()).
    void insert(std::uint32_t i, const Vec3& centre);
    /// Empties every cell.
    void clear();
    /// Bins every centre anew.
    void rebuild(const std::vector<Vec3>& centres);

    /// Calls visit(j) for every sphere j in the cells around point (each once).
    template <typename Visit> void forEachNear(const Vec3& point, Visit visit) const {
        const std::array<int, 3> cell = cellOf(point);
        std::array<std::array<int, 3>, 3> neighbours{};
        std::array<int, 3> counts{};
        for (int a = 0; a < 3; ++a) counts[a] = neighbourCells(cell[a], a, neighbours[a]);
        for (int i = 0; i < counts[0]; ++i)
            for (int j = 0; j < counts[1]; ++j)
                for (int k = 0; k < counts[2]; ++k)
                    for (std::int32_t s =
                             head_[index(neighbours[0][i], neighbours[1][j], neighbours[2][k])];
                         s >= 0; s = next_[static_cast<std::size_t>(s)])
                        visit(static_cast<std::uint32_t>(s));
    }

private:
    std::array<int, 3> cellOf(const Vec3& point) const;
    /// The distinct cells next to cell c along axis a (wrapped when periodic); their count.
    int neighbourCells(int c, int a, std::array<int, 3>& out) const;
    std::size_t index(int i, int j, int k) const {
        return (static_cast<std::size_t>(i) * static_cast<std::size_t>(cells_[1]) +
                static_cast<std::size_t>(j)) *
                   static_cast<std::size_t>(cells_[2]) +
               static_cast<std::size_t>(k);
    }

    Vec3 lower_;
    Vec3 cellSize_;
    std::array<int, 3> cells_{};
    bool periodic_;
    std::vector<std::int32_t> head_; ///< first sphere of each cell, −1: none
    std::vector<std::int32_t> next_; ///< the next sphere of the same cell, −1: none
};

} // namespace slides
