#include "slides/carrier/foam_interpolation.h"

#include <Eigen/Eigenvalues>

namespace slides {

namespace {

bool givesBoundaryValues(PatchType type) {
    return type == PatchType::patch || type == PatchType::wall;
}

struct PointFit {
    std::vector<double> weights;
    bool rankDeficient = false; ///< the samples do not fix a linear function (e.g. coplanar)
};

PointFit fitPoint(const FoamMesh& mesh, const Vec3& here, const std::vector<int>& samples) {
    std::vector<Vec3> positions;
    for (const int s : samples)
        positions.push_back(s < mesh.cellCount ? mesh.cellCentres[s]
                                               : mesh.faceCentres[s - mesh.cellCount]);
    PointFit fit;
    fit.weights = pointFitWeights(here, positions, fit.rankDeficient);
    return fit;
}

} // namespace

// Weighted least squares for φ(x) = φ̄ + g·(x − x̄) about the weighted mean x̄ of the samples,
// w = 1/|x − x_p|²: g = C⁺ Σ w_k (x_k − x̄) φ_k with C = Σ w_k (x_k − x̄)(x_k − x̄)ᵀ, so the
// point value is Σ_k α_k φ_k with α_k = w_k/W + w_k (x_p − x̄)ᵀ C⁺ (x_k − x̄). Exact for linear φ
// when C has full rank; with samples in a plane (2-D, wedge) the pseudo-inverse fits within the
// plane.
std::vector<double> pointFitWeights(const Vec3& here, std::span<const Vec3> positions,
                                    bool& rankDeficient) {
    double scale = 0;
    for (const Vec3& x : positions) scale = std::max(scale, (x - here).norm());
    std::vector<Vec3> offsets; // scaled: the fit is well conditioned
    std::vector<double> weights;
    Vec3 mean = Vec3::Zero();
    double total = 0;
    for (const Vec3& x : positions) {
        offsets.push_back((x - here) / scale);
        weights.push_back(1 / std::max(offsets.back().squaredNorm(), 1e-24));
        mean += weights.back() * offsets.back();
        total += weights.back();
    }
    mean /= total;
    Mat3 spread = Mat3::Zero();
    for (std::size_t k = 0; k < positions.size(); ++k)
        spread += weights[k] * (offsets[k] - mean) * (offsets[k] - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Mat3> eigen(spread);
    const double largest = eigen.eigenvalues().maxCoeff();
    Vec3 inverse = Vec3::Zero();
    rankDeficient = false;
    for (int i = 0; i < 3; ++i) {
        const double value = eigen.eigenvalues()[i];
        if (value > 1e-12 * largest) inverse[i] = 1 / value;
        if (value < 1e-3 * largest) rankDeficient = true; // or nearly: ill-conditioned
    }
    const Vec3 toPoint = eigen.eigenvectors() * inverse.asDiagonal() *
                         eigen.eigenvectors().transpose() * (-mean); // C⁺ (x_p − x̄)
    std::vector<double> alphas;
    for (std::size_t k = 0; k < positions.size(); ++k)
        alphas.push_back(weights[k] / total + weights[k] * toPoint.dot(offsets[k] - mean));
    return alphas;
}

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
        PointFit fit = fitPoint(mesh, mesh.points[p], list);
        if (fit.rankDeficient) { // too few samples about a boundary point: add the next cells
            std::vector<int> wider = list;
            for (const int s : list)
                if (s < mesh.cellCount)
                    for (const int f : mesh.facesOf(s))
                        if (const int next = mesh.across(f, s); next >= 0) wider.push_back(next);
            std::sort(wider.begin(), wider.end());
            wider.erase(std::unique(wider.begin(), wider.end()), wider.end());
            list = wider;
            fit = fitPoint(mesh, mesh.points[p], list);
        }
        samples_.insert(samples_.end(), list.begin(), list.end());
        weights_.insert(weights_.end(), fit.weights.begin(), fit.weights.end());
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
template std::vector<GasValues> PointWeights::pointValues(const FoamVolField<GasValues>&) const;

template <typename T>
InterpolableField<T>::InterpolableField(const FoamVolField<T>& field, const FoamMesh& mesh,
                                        const PointWeights& weights)
    : cells(field.cells), points(weights.pointValues(field)) {
    refreshFaceMidpoints(mesh);
}

template <typename T> void InterpolableField<T>::refreshFaceMidpoints(const FoamMesh& mesh) {
    faceMidpoints.resize(mesh.faceCount());
    for (int f = 0; f < mesh.faceCount(); ++f) {
        T sum = T(0.0 * cells[0]);
        for (const int p : mesh.pointsOf(f)) sum += points[p];
        faceMidpoints[f] = sum / static_cast<double>(mesh.pointsOf(f).size());
    }
}

template <typename T> T InterpolableField<T>::value(const FoamMesh&, const TetLocation& at) const {
    return T(at.weights[0] * cells[at.cell] + at.weights[1] * faceMidpoints[at.face] +
             at.weights[2] * points[at.points[0]] + at.weights[3] * points[at.points[1]]);
}

template struct InterpolableField<double>;
template struct InterpolableField<Vec3>;
template struct InterpolableField<GasValues>;

template <typename T>
Mat3 tetGradient(const FoamMesh& mesh, const FoamLocator& locator,
                 const InterpolableField<T>& velocity, const TetLocation& at) {
    const auto ring = mesh.pointsOf(at.face);
    const int n = static_cast<int>(ring.size());
    return tetGradient(locator, at,
                       {velocityOf(velocity.cells[at.cell]),
                        velocityOf(velocity.faceMidpoints[at.face]),
                        velocityOf(velocity.points[ring[at.edge]]),
                        velocityOf(velocity.points[ring[(at.edge + 1) % n]])});
}

Mat3 tetGradient(const FoamLocator& locator, const TetLocation& at,
                 const std::array<Vec3, 4>& vertexVelocities) {
    const auto tet = locator.vertices(at.cell, at.face, at.edge);
    const Vec3& u0 = vertexVelocities[0];
    Mat3 edges, differences;
    edges << tet[1] - tet[0], tet[2] - tet[0], tet[3] - tet[0];
    differences << vertexVelocities[1] - u0, vertexVelocities[2] - u0, vertexVelocities[3] - u0;
    // U(x) − U0 = G (x − x0) for each edge: G E = ΔU.
    return differences * edges.inverse();
}

template <typename T>
std::vector<Mat3> cellGradients(const FoamMesh& mesh, const FoamLocator& locator,
                                const InterpolableField<T>& velocity) {
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

template Mat3 tetGradient(const FoamMesh&, const FoamLocator&, const InterpolableField<Vec3>&,
                          const TetLocation&);
template Mat3 tetGradient(const FoamMesh&, const FoamLocator&, const InterpolableField<GasValues>&,
                          const TetLocation&);
template std::vector<Mat3> cellGradients(const FoamMesh&, const FoamLocator&,
                                         const InterpolableField<Vec3>&);
template std::vector<Mat3> cellGradients(const FoamMesh&, const FoamLocator&,
                                         const InterpolableField<GasValues>&);

} // namespace slides
