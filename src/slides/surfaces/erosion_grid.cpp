#include "slides/surfaces/erosion_grid.h"

#include "slides/physics/damage_stress.h"
#include "slides/physics/porous_moduli.h"

#include <cmath>
#include <limits>

namespace slides {

namespace {

/// Two unit vectors completing the normal to a right-handed frame.
Mat3 layerAxes(const Vec3& normal) {
    const Vec3 seed = std::abs(normal.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    const Vec3 first = (seed - seed.dot(normal) * normal).normalized();
    Mat3 axes;
    axes.col(0) = first;
    axes.col(1) = (-normal).cross(first);
    axes.col(2) = -normal;
    return axes;
}

} // namespace

ErosionGrid::ErosionGrid(const Vec3& point, const Vec3& normal, const MaterialSettings& matrix,
                         const ErosionSettings& settings)
    : axes_(layerAxes(normal)), cells_(settings.cells), threshold_(settings.threshold) {
    spacing_ = Vec3(settings.width / cells_[0], settings.width / cells_[1],
                    settings.thickness / cells_[2]);
    origin_ = point - 0.5 * settings.width * (axes_.col(0) + axes_.col(1));
    const IsotropicModuli porous = porousModuli({matrix.bulkModulus, matrix.shearModulus},
                                                settings.porosity, settings.boundWeight);
    layerModuli_ = matrix;
    layerModuli_.bulkModulus = porous.bulk;
    layerModuli_.shearModulus = porous.shear;
    layer_ = layerModuli_.elasticMaterial();
    concentration_ = matrix.elasticMaterial().youngsModulus / layer_.youngsModulus;
    const auto p = points();
    damage_.assign(static_cast<std::size_t>(p[0]) * p[1] * p[2], 0);
    peak_.assign(damage_.size(), 0.0);
}

HertzLoad ErosionGrid::impactLoad(double radius, double mass, const MaterialSettings& particle,
                                  double normalSpeed, double tangentialRatio) const {
    constexpr double infinite = std::numeric_limits<double>::infinity();
    const ContactPair pair =
        contactPair({mass, radius, &particle}, {infinite, infinite, &layerModuli_});
    const double overlap = std::pow(15 * pair.mass * normalSpeed * normalSpeed /
                                        (16 * pair.youngsModulus * std::sqrt(pair.radius)),
                                    0.4);
    const double normal =
        4.0 / 3 * pair.youngsModulus * std::sqrt(pair.radius) * std::pow(overlap, 1.5);
    return {normal, tangentialRatio * normal, std::sqrt(pair.radius * overlap)};
}

void ErosionGrid::applyImpact(double time, const Vec3& contact, const Vec3& tangent,
                              const HertzLoad& load) {
    ++impacts_;
    CentreLineStress centre{time, std::vector<double>(static_cast<std::size_t>(points()[2]))};
    // The contact frame: x along the tangential load, z the depth.
    const Vec3 depth = axes_.col(2);
    const Vec3 across = depth.cross(tangent);
    const auto p = points();
    for (int k = 0; k < p[2]; ++k)
        for (int j = 0; j < p[1]; ++j)
            for (int i = 0; i < p[0]; ++i) {
                const Vec3 offset = position(i, j, k) - contact;
                const Vec3 local(offset.dot(tangent), offset.dot(across), offset.dot(depth));
                // Cerruti's superposition is singular at its sources on the surface: the
                // surface points are evaluated a tenth of a cell deep.
                const Vec3 at(local.x(), local.y(), std::max(local.z(), 0.1 * spacing_.z()));
                const double equivalent =
                    concentration_ * equivalentStress(contactStress(load, at, layer_.poissonRatio),
                                                      layer_.poissonRatio);
                const std::size_t n = index(i, j, k);
                if (damageIndicator(equivalent, threshold_) > 0) ++damage_[n];
                peak_[n] = std::max(peak_[n], equivalent);
                if (2 * i == cells_[0] && 2 * j == cells_[1])
                    centre.equivalentStress[static_cast<std::size_t>(k)] = equivalent;
            }
    history_.push_back(std::move(centre));
}

Vec3 ErosionGrid::position(int i, int j, int k) const {
    return origin_ + axes_ * Vec3(i * spacing_.x(), j * spacing_.y(), k * spacing_.z());
}

double ErosionGrid::damagedVolume() const {
    const auto p = points();
    // Trapezoid weights: a boundary point holds half a cell along each axis it bounds.
    const auto share = [](int n, int count) { return n == 0 || n == count - 1 ? 0.5 : 1.0; };
    double volume = 0;
    for (int k = 0; k < p[2]; ++k)
        for (int j = 0; j < p[1]; ++j)
            for (int i = 0; i < p[0]; ++i)
                if (damage_[index(i, j, k)] > 0)
                    volume += share(i, p[0]) * share(j, p[1]) * share(k, p[2]);
    return volume * spacing_.prod();
}

} // namespace slides
