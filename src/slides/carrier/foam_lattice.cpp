#include "slides/carrier/foam_lattice.h"

#include <algorithm>
#include <cmath>

namespace slides {

FoamLattice::FoamLattice(const LatticeFrame& frame, const Sampler& sample,
                         std::array<bool, 3> keepScalar)
    : frame_(frame) {
    const auto& n = frame_.nodes;
    const std::size_t count = static_cast<std::size_t>(n[0]) * static_cast<std::size_t>(n[1]) *
                              static_cast<std::size_t>(n[2]);
    velocity_.assign(count, Vec3::Zero());
    for (int s = 0; s < 3; ++s)
        if (keepScalar[s]) scalars_[s].assign(count, 0.0);
    inside_.assign(count, 0);
    for (int k = 0; k < n[2]; ++k)
        for (int j = 0; j < n[1]; ++j)
            for (int i = 0; i < n[0]; ++i) {
                const Vec3 x = frame_.origin + frame_.spacing * (frame_.axes * Vec3(i, j, k));
                const auto values = sample(x);
                if (!values) continue;
                const std::size_t node = nodeIndex(i, j, k);
                inside_[node] = 1;
                velocity_[node] = values->velocity;
                for (int s = 0; s < 3; ++s)
                    if (!scalars_[s].empty()) scalars_[s][node] = values->scalars[s];
            }
    // A cell (by its lowest node) is usable when its nodes, up to 8, are all inside.
    cellInside_.assign(count, 0);
    const int di = n[0] > 1, dj = n[1] > 1, dk = n[2] > 1;
    for (int k = 0; k + dk < n[2]; ++k)
        for (int j = 0; j + dj < n[1]; ++j)
            for (int i = 0; i + di < n[0]; ++i)
                cellInside_[nodeIndex(i, j, k)] =
                    inside_[nodeIndex(i, j, k)] && inside_[nodeIndex(i + di, j, k)] &&
                    inside_[nodeIndex(i, j + dj, k)] && inside_[nodeIndex(i + di, j + dj, k)] &&
                    inside_[nodeIndex(i, j, k + dk)] && inside_[nodeIndex(i + di, j, k + dk)] &&
                    inside_[nodeIndex(i, j + dj, k + dk)] &&
                    inside_[nodeIndex(i + di, j + dj, k + dk)];
}

bool FoamLattice::locate(const Vec3& point, LatticeWeights& out) const {
    const Vec3 local = frame_.axes.transpose() * (point - frame_.origin) / frame_.spacing;
    std::array<int, 3> base{}, step{};
    std::array<double, 3> t{};
    for (int d = 0; d < 3; ++d) {
        const int n = frame_.nodes[d];
        if (n == 1) continue;                                    // a plane: base 0, t 0, no step
        if (!(local[d] >= 0 && local[d] <= n - 1)) return false; // also NaN
        base[d] = std::min(static_cast<int>(local[d]), n - 2);
        t[d] = local[d] - base[d];
        step[d] = 1;
    }
    if (!cellInside_[nodeIndex(base[0], base[1], base[2])]) return false;
    for (int c = 0; c < 8; ++c) {
        const std::array<int, 3> corner{c & 1, (c >> 1) & 1, (c >> 2) & 1};
        std::array<double, 3> factor{};
        for (int d = 0; d < 3; ++d) factor[d] = corner[d] ? t[d] : 1 - t[d];
        out.node[c] = nodeIndex(base[0] + corner[0] * step[0], base[1] + corner[1] * step[1],
                                base[2] + corner[2] * step[2]);
        out.weight[c] = factor[0] * factor[1] * factor[2];
        Vec3 derivative; // ∂weight/∂ξ_d, ξ in node units
        for (int d = 0; d < 3; ++d)
            derivative[d] =
                step[d] == 0 ? 0.0
                             : (corner[d] ? 1.0 : -1.0) * factor[(d + 1) % 3] * factor[(d + 2) % 3];
        out.gradient[c] = frame_.axes * derivative / frame_.spacing;
    }
    return true;
}

Vec3 FoamLattice::velocity(const LatticeWeights& at) const {
    Vec3 sum = Vec3::Zero();
    for (int c = 0; c < 8; ++c) sum += at.weight[c] * velocity_[at.node[c]];
    return sum;
}

Mat3 FoamLattice::velocityGradient(const LatticeWeights& at) const {
    Mat3 sum = Mat3::Zero();
    for (int c = 0; c < 8; ++c) sum += velocity_[at.node[c]] * at.gradient[c].transpose();
    return sum;
}

double FoamLattice::scalar(int which, const LatticeWeights& at) const {
    const auto& values = scalars_[which];
    if (values.empty()) return 0;
    double sum = 0;
    for (int c = 0; c < 8; ++c) sum += at.weight[c] * values[at.node[c]];
    return sum;
}

std::size_t FoamLattice::nodesInside() const {
    return static_cast<std::size_t>(std::count(inside_.begin(), inside_.end(), 1));
}

} // namespace slides
