#include "slides/carrier/foam_interpolation.h"

#include <Eigen/Eigenvalues>

namespace slides {

namespace {

bool givesBoundaryValues(PatchType type) {
    return type == PatchType::patch || type == PatchType::wall;
}

} // namespace

PointWeights::PointWeights(const FoamMesh& mesh) : mesh_(mesh) {
    const int pointCount = static_cast<int>(mesh.points.size());
    // Samples around each point: the cells using it and the boundary faces holding it.
    std::vector<std::vector<int>> around(pointCount);
    for (int f = 0; f < mesh.faceCount(); ++f) {
        const int patch = mesh.facePatch[f];
        for (const int p : mesh.pointsOf(f)) {
            around[p].push_back(mesh.owner[f]);
            if (f < mesh.internalFaceCount()) around[p].push_back(mesh.neighbour[f]);
            if (patch >= 0 && givesBoundaryValues(mesh.patches[patch].type))
                around[p].push_back(mesh.cellCount + f);
        }
    }
    offsets_.assign(pointCount + 1, 0);
    for (int p = 0; p < pointCount; ++p) {
        auto& list = around[p];
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
        // Weighted least squares for φ(x) = a + g·(x − x_p) with w = 1/|x − x_p|²; the point
        // value is a = Σ w_k r·(1, d_k) φ_k with r = M⁺ e0, M = Σ w_k (1, d_k)(1, d_k)ᵀ.
        const Vec3& here = mesh.points[p];
        std::vector<Eigen::Vector4d> rows;
        std::vector<double> rowWeights;
        double scale = 0;
        for (const int s : list) {
            const Vec3& at =
                s < mesh.cellCount ? mesh.cellCentres[s] : mesh.faceCentres[s - mesh.cellCount];
            scale = std::max(scale, (at - here).norm());
        }
        Eigen::Matrix4d normal = Eigen::Matrix4d::Zero();
        for (const int s : list) {
            const Vec3& at =
                s < mesh.cellCount ? mesh.cellCentres[s] : mesh.faceCentres[s - mesh.cellCount];
            const Vec3 d = (at - here) / scale; // scaled: the fit is well conditioned
            const double w = 1 / std::max(d.squaredNorm(), 1e-24);
            Eigen::Vector4d row(1, d.x(), d.y(), d.z());
            rows.push_back(row);
            rowWeights.push_back(w);
            normal += w * row * row.transpose();
        }
        // Pseudo-inverse: samples in a plane (2-D and wedge meshes) leave one direction unfit.
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eigen(normal);
        const double largest = eigen.eigenvalues().maxCoeff();
        Eigen::Vector4d inverse = Eigen::Vector4d::Zero();
        for (int i = 0; i < 4; ++i)
            if (eigen.eigenvalues()[i] > 1e-12 * largest) inverse[i] = 1 / eigen.eigenvalues()[i];
        const Eigen::Vector4d r = eigen.eigenvectors() * inverse.asDiagonal() *
                                  eigen.eigenvectors().transpose() * Eigen::Vector4d::UnitX();
        for (std::size_t k = 0; k < list.size(); ++k) {
            samples_.push_back(list[k]);
            weights_.push_back(rowWeights[k] * r.dot(rows[k]));
        }
        offsets_[p + 1] = static_cast<int>(samples_.size());
    }
}

template <typename T> std::vector<T> PointWeights::pointValues(const FoamVolField<T>& field) const {
    const int cellCount = mesh_.cellCount;
    std::vector<T> values(mesh_.points.size());
    for (std::size_t p = 0; p < values.size(); ++p) {
        T sum = T(0.0 * field.cells[0]);
        for (int k = offsets_[p]; k < offsets_[p + 1]; ++k) {
            const int s = samples_[k];
            if (s < cellCount) {
                sum += weights_[k] * field.cells[s];
                continue;
            }
            const int face = s - cellCount;
            const int patch = mesh_.facePatch[face];
            const auto& patchValues = field.patchValues[patch];
            sum += weights_[k] * (patchValues.empty()
                                      ? field.cells[mesh_.owner[face]]
                                      : patchValues[face - mesh_.patches[patch].start]);
        }
        values[p] = sum;
    }
    return values;
}

template std::vector<double> PointWeights::pointValues(const FoamVolField<double>&) const;
template std::vector<Vec3> PointWeights::pointValues(const FoamVolField<Vec3>&) const;

template <typename T>
InterpolableField<T>::InterpolableField(const FoamVolField<T>& field, const FoamMesh& mesh,
                                        const PointWeights& weights)
    : cells(field.cells), points(weights.pointValues(field)) {
    faceMidpoints.resize(mesh.faceCount());
    for (int f = 0; f < mesh.faceCount(); ++f) {
        T sum = T(0.0 * cells[0]);
        for (const int p : mesh.pointsOf(f)) sum += points[p];
        faceMidpoints[f] = sum / static_cast<double>(mesh.pointsOf(f).size());
    }
}

template <typename T>
T InterpolableField<T>::value(const FoamMesh& mesh, const TetLocation& at) const {
    const auto ring = mesh.pointsOf(at.face);
    const int n = static_cast<int>(ring.size());
    return T(at.weights[0] * cells[at.cell] + at.weights[1] * faceMidpoints[at.face] +
             at.weights[2] * points[ring[at.edge]] +
             at.weights[3] * points[ring[(at.edge + 1) % n]]);
}

template struct InterpolableField<double>;
template struct InterpolableField<Vec3>;

Mat3 tetGradient(const FoamMesh& mesh, const FoamLocator& locator,
                 const InterpolableField<Vec3>& velocity, const TetLocation& at) {
    const auto tet = locator.vertices(at.cell, at.face, at.edge);
    const auto ring = mesh.pointsOf(at.face);
    const int n = static_cast<int>(ring.size());
    const Vec3 u0 = velocity.cells[at.cell];
    Mat3 edges, differences;
    edges << tet[1] - tet[0], tet[2] - tet[0], tet[3] - tet[0];
    differences << velocity.faceMidpoints[at.face] - u0, velocity.points[ring[at.edge]] - u0,
        velocity.points[ring[(at.edge + 1) % n]] - u0;
    // U(x) − U0 = G (x − x0) for each edge: G E = ΔU.
    return differences * edges.inverse();
}

std::vector<Mat3> cellGradients(const FoamMesh& mesh, const FoamLocator& locator,
                                const InterpolableField<Vec3>& velocity) {
    std::vector<Mat3> gradients(mesh.cellCount, Mat3::Zero());
    for (int c = 0; c < mesh.cellCount; ++c) {
        double volume = 0;
        for (const int f : mesh.facesOf(c)) {
            const int n = static_cast<int>(mesh.pointsOf(f).size());
            for (int edge = 0; edge < n; ++edge) {
                const auto tet = locator.vertices(c, f, edge);
                const double v =
                    std::abs((tet[1] - tet[0]).dot((tet[2] - tet[0]).cross(tet[3] - tet[0]))) / 6;
                if (v == 0) continue;
                gradients[c] +=
                    v * tetGradient(mesh, locator, velocity, TetLocation{c, f, edge, {}, -1});
                volume += v;
            }
        }
        if (volume > 0) gradients[c] /= volume;
    }
    return gradients;
}

} // namespace slides
