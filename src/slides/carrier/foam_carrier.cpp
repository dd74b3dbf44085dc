#include "slides/carrier/foam_carrier.h"

#include "slides/carrier/foam_file.h"
#include "slides/carrier/gas_records.h"
#include "slides/core/error.h"
#include "slides/core/name_table.h"
#include "slides/core/parallel.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>

namespace slides {

namespace {

Vec3 patchNormal(const FoamMesh& mesh, const FoamPatch& patch) {
    Vec3 sum = Vec3::Zero();
    for (int f = patch.start; f < patch.start + patch.size; ++f) sum += mesh.faceAreas[f];
    return sum.normalized();
}

std::optional<WedgeFrame> findWedge(const FoamMesh& mesh, const std::string& file) {
    std::vector<const FoamPatch*> wedges;
    for (const auto& patch : mesh.patches)
        if (patch.type == PatchType::wedge && patch.size > 0) wedges.push_back(&patch);
    if (wedges.empty()) return std::nullopt;
    if (wedges.size() != 2)
        throw InputError(file, 0, "",
                         "an axisymmetric mesh needs exactly two wedge patches, found " +
                             std::to_string(wedges.size()));
    const Vec3 n1 = patchNormal(mesh, *wedges[0]), n2 = patchNormal(mesh, *wedges[1]);
    WedgeFrame frame;
    frame.axis = n1.cross(n2);
    if (!(frame.axis.norm() > 1e-8))
        throw InputError(file, 0, "", "the wedge patches are parallel: no axis");
    frame.axis.normalize();
    // The axis: where the two wedge planes meet (the point of it nearest the origin).
    Mat3 planes;
    planes << n1.transpose(), n2.transpose(), frame.axis.transpose();
    const Vec3 offsets(n1.dot(mesh.faceCentres[wedges[0]->start]),
                       n2.dot(mesh.faceCentres[wedges[1]->start]), 0.0);
    frame.origin = planes.inverse() * offsets;
    // The patches' outward normals enclose π − θ.
    frame.angle = std::numbers::pi - std::acos(std::clamp(n1.dot(n2), -1.0, 1.0));
    const Vec3 centrePlaneNormal = (n1 - n2).normalized();
    frame.radial = frame.axis.cross(centrePlaneNormal).normalized();
    Vec3 centroid = Vec3::Zero();
    for (const Vec3& centre : mesh.cellCentres) centroid += centre;
    centroid /= static_cast<double>(mesh.cellCount);
    if ((centroid - frame.origin).dot(frame.radial) < 0) frame.radial = -frame.radial;
    return frame;
}

} // namespace

Vec3 WedgeFrame::toWedge(const Vec3& x, Mat3& rotation) const {
    const Vec3 d = x - origin;
    const double axial = d.dot(axis);
    const Vec3 across = d - axial * axis;
    const double radius = across.norm();
    rotation.setIdentity();
    if (radius > 0) {
        const Vec3 direction = across / radius;
        const double angle = std::atan2(axis.dot(radial.cross(direction)), radial.dot(direction));
        rotation = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
    }
    return origin + axial * axis + radius * radial;
}

FoamCarrier::FoamCarrier(const std::filesystem::path& caseDirectory, FoamCarrierSettings settings)
    : timeDirectory_(foamTimeDirectory(caseDirectory, settings.time)), settings_(settings),
      mesh_(readFoamMesh(caseDirectory)) {
    const std::string meshFile = (caseDirectory / "constant" / "polyMesh" / "boundary").string();
    if (mesh_.cellCount == 0) throw InputError(meshFile, 0, "", "the mesh has no cells");
    if (mesh_.facePoints.size() >= std::size_t{1} << 30) // FoamLocator's tetrahedron indices
        throw InputError((caseDirectory / "constant" / "polyMesh" / "faces").string(), 0, "",
                         "the mesh's faces hold 2³⁰ points or more: too large to track on");
    locator_ = std::make_unique<FoamLocator>(mesh_);
    wedge_ = findWedge(mesh_, meshFile);
    for (const auto& patch : mesh_.patches)
        if (!wedge_ && patch.type == PatchType::empty && patch.size > 0 && !emptyNormal_)
            emptyNormal_ = mesh_.faceAreas[patch.start].normalized();

    // A part of a decomposed case keeps the fields as read for shareProcessorPoints().
    const bool part =
        std::any_of(mesh_.patches.begin(), mesh_.patches.end(),
                    [](const FoamPatch& p) { return p.type == PatchType::processor; });
    if (settings_.series) {
        const std::string key = "carrier.foamFieldCoeffs.";
        if (settings_.interpolation != FoamInterpolation::cellPoint)
            throw InputError(caseDirectory.string(), 0, key + "interpolation",
                             "a time series is interpolated by cellPoint only");
        if (part)
            throw InputError(caseDirectory.string(), 0, key + "times",
                             "a time series is not tracked in parallel runs yet");
        series_ = std::make_unique<FoamSeries>(caseDirectory, *settings_.series, mesh_);
        timeDirectory_ = series_->firstDirectory();
        return;
    }
    // U, then k, ε and T where present, as one record per cell, face and point.
    hasScalar_ = gasScalarsIn(timeDirectory_);
    auto gas = readGasRecords(timeDirectory_, mesh_, hasScalar_);
    gas_ = std::make_unique<InterpolableField<GasValues>>(gas, mesh_, PointWeights(mesh_));
    if (part) gasRead_ = std::move(gas);
    if (settings_.interpolation == FoamInterpolation::cell)
        cellGradients_ = cellGradients(mesh_, *locator_, *gas_);
    if (settings_.interpolation == FoamInterpolation::lattice) buildLattice(caseDirectory);
}

void FoamCarrier::shareProcessorPoints(const PartAddressing& addressing,
                                       const PartAllGather& allGather) {
    // A part without processor patches (the only one) shares no point, but takes part.
    const SharedPointWeights shared(mesh_, addressing, allGather);
    shared.apply(gasRead_.value_or(FoamVolField<GasValues>{}), gas_->points);
    gas_->refreshFaceMidpoints(mesh_);
    gasRead_.reset();
    if (settings_.interpolation == FoamInterpolation::cell)
        cellGradients_ = cellGradients(mesh_, *locator_, *gas_);
}

std::optional<GasValues> FoamCarrier::cellPointValues(const Vec3& x, int& tet) const {
    const TetLocation at = locator_->locateFrom(x, tet);
    if (!at.found()) return std::nullopt;
    tet = at.tet;
    return gas_->value(mesh_, at);
}

void FoamCarrier::buildLattice(const std::filesystem::path& caseDirectory) {
    // Directions, and the coordinates of the points sampleAt maps to along them: (axial,
    // radial, hoop = 0) about a wedge's axis; in-plane, in-plane, normal for a 2-D mesh.
    LatticeFrame frame;
    Vec3 base = Vec3::Zero();
    bool planar = false;
    if (wedge_) {
        frame.axes << wedge_->axis, wedge_->radial, wedge_->axis.cross(wedge_->radial);
        base = wedge_->origin;
        planar = true;
    } else if (emptyNormal_) {
        const Vec3& normal = *emptyNormal_;
        const Vec3 across =
            (std::abs(normal.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(normal).normalized();
        frame.axes << across, normal.cross(across), normal;
        planar = true;
    }
    Vec3 low = Vec3::Constant(INFINITY), high = Vec3::Constant(-INFINITY);
    for (const Vec3& point : mesh_.points) {
        Vec3 local = frame.axes.transpose() * (point - base);
        if (wedge_) local = Vec3(local[0], std::hypot(local[1], local[2]), 0.0);
        low = low.cwiseMin(local);
        high = high.cwiseMax(local);
    }
    if (emptyNormal_) low[2] = high[2] = mesh_.cellCentres[0].dot(*emptyNormal_);
    if (wedge_) low[2] = high[2] = 0;
    frame.spacing =
        settings_.latticeSpacing > 0 ? settings_.latticeSpacing : (high - low).maxCoeff() / 100;
    double nodes = 1;
    for (int d = 0; d < 3; ++d) {
        frame.nodes[d] =
            planar && d == 2 ? 1 : 2 + static_cast<int>((high[d] - low[d]) / frame.spacing);
        nodes *= frame.nodes[d];
    }
    if (nodes > 5e7)
        throw InputError((caseDirectory / "constant" / "slidesProperties").string(), 0,
                         "carrier.foamFieldCoeffs.latticeSpacing",
                         "gives " + std::to_string(static_cast<long>(nodes)) +
                             " lattice nodes over the mesh (at most 5e7): choose a larger spacing");
    frame.origin = base + frame.axes * low;
    int tet = -1;
    lattice_ = std::make_unique<FoamLattice>(
        frame, [&](const Vec3& x) { return cellPointValues(x, tet); }, hasScalar_);

    // Its error against cellPoint at random points of the mesh (those the lattice serves).
    double reference = 0;
    for (const GasValues& cell : gas_->cells) reference = std::max(reference, cell.velocity.norm());
    std::mt19937 random(1);
    std::uniform_real_distribution<double> unit(0, 1);
    double worst = 0, squares = 0;
    int served = 0, exact = 0;
    for (int attempt = 0; attempt < 100000 && served + exact < 4000; ++attempt) {
        Vec3 at;
        for (int d = 0; d < 3; ++d) at[d] = unit(random) * (frame.nodes[d] - 1);
        const Vec3 x = frame.origin + frame.spacing * (frame.axes * at);
        const auto expected = cellPointValues(x, tet);
        if (!expected) continue;
        LatticeWeights weights;
        if (!lattice_->locate(x, weights)) {
            ++exact;
            continue;
        }
        const double error =
            (lattice_->velocity(weights) - expected->velocity).norm() / std::max(reference, 1e-300);
        worst = std::max(worst, error);
        squares += error * error;
        ++served;
    }
    char text[400];
    std::snprintf(text, sizeof text,
                  "lattice %.3g m, %d×%d×%d nodes (%.0f %% in the mesh); |ΔU|/U_ref against "
                  "cellPoint at %d random points: max %.2e, rms %.2e (U_ref = %.4g m/s, the "
                  "largest cell |U|); %d more near the boundary take the exact path",
                  frame.spacing, frame.nodes[0], frame.nodes[1], frame.nodes[2],
                  100.0 * static_cast<double>(lattice_->nodesInside()) / nodes, served, worst,
                  served > 0 ? std::sqrt(squares / served) : 0.0, reference, exact);
    latticeReport_ = text;
    latticeFigures_ = {{"latticeSpacing", frame.spacing},
                       {"latticeErrorMax", worst},
                       {"latticeErrorRms", served > 0 ? std::sqrt(squares / served) : 0.0},
                       {"latticeErrorPoints", served},
                       {"latticeExactPathPoints", exact}};
}

Mat3 FoamCarrier::wedgeHoopGradient(const Mat3& gradient, const Vec3& velocity,
                                    const Vec3& x) const {
    if (!wedge_) return gradient;
    // Axisymmetric field in cylindrical coordinates: ∂U/∂(rθ) = (u_r/r) e_θ − (u_θ/r) e_r, a
    // column the one cell thick wedge cannot resolve; it replaces the tetrahedron's e_θ column.
    const double radius = (x - wedge_->origin).dot(wedge_->radial);
    if (!(radius > 0)) return gradient;
    const Vec3 hoop = wedge_->axis.cross(wedge_->radial);
    const Vec3 column =
        (velocity.dot(wedge_->radial) * hoop - velocity.dot(hoop) * wedge_->radial) / radius;
    return gradient - (gradient * hoop) * hoop.transpose() + column * hoop.transpose();
}

void FoamCarrier::missing(const std::string& field) const {
    throw InputError((timeDirectory_ / field).string(), 0, "",
                     "missing field " + field + ", needed by the chosen physics");
}

void FoamCarrier::sampleLevelsAt(const TetLocation& at, const Vec3& x, const Mat3& rotation,
                                 const LevelCache<FoamLevel>::Pair& levels, CarrierNeeds needs,
                                 CarrierSample& out, std::size_t i) const {
    // The tetrahedron's vertex records of both levels, linear in time, then linear in space: one
    // pass gives U, ∇U, k, ε and T at t, and ∂U/∂t as the levels' difference over the interval.
    const auto before = levels.before->vertexValues(at), after = levels.after->vertexValues(at);
    const double weight = levels.bracket.weight;
    std::array<Vec3, 4> velocities;
    GasValues here;
    Vec3 change = Vec3::Zero();
    for (int k = 0; k < 4; ++k) {
        const GasValues now = (1 - weight) * before[k] + weight * after[k];
        velocities[k] = now.velocity;
        here += at.weights[k] * now;
        change += at.weights[k] * (after[k].velocity - before[k].velocity);
    }
    out.velocity[i] = rotation * here.velocity;
    if (needs.timeDerivative)
        out.velocityTimeDerivative[i] = rotation * (change / levels.bracket.interval);
    if (needs.velocityGradient)
        out.velocityGradient[i] =
            rotation * wedgeHoopGradient(tetGradient(*locator_, at, velocities), here.velocity, x) *
            rotation.transpose();
    if (needs.turbulence) {
        out.turbulentKineticEnergy[i] = here.scalars[0];
        out.dissipationRate[i] = here.scalars[1];
    }
    if (needs.temperature) out.temperature[i] = here.scalars[2];
}

Vec3 FoamCarrier::meshPoint(const Vec3& point, Mat3& rotation) const {
    rotation.setIdentity();
    Vec3 x = point;
    if (wedge_) x = wedge_->toWedge(point, rotation);
    if (emptyNormal_) x -= (x - mesh_.cellCentres[0]).dot(*emptyNormal_) * *emptyNormal_;
    return x;
}

void FoamCarrier::sampleAt(const Vec3& point, std::int32_t& location, CarrierNeeds needs,
                           CarrierSample& out, std::size_t i,
                           const LevelCache<FoamLevel>::Pair* levels) const {
    Mat3 rotation;
    const Vec3 x = meshPoint(point, rotation);
    if (LatticeWeights weights; lattice_ && lattice_->locate(x, weights)) {
        const Vec3 velocity = lattice_->velocity(weights);
        out.velocity[i] = rotation * velocity;
        if (needs.velocityGradient)
            out.velocityGradient[i] =
                rotation * wedgeHoopGradient(lattice_->velocityGradient(weights), velocity, x) *
                rotation.transpose();
        if (needs.turbulence) {
            out.turbulentKineticEnergy[i] = lattice_->scalar(0, weights);
            out.dissipationRate[i] = lattice_->scalar(1, weights);
        }
        if (needs.temperature) out.temperature[i] = lattice_->scalar(2, weights);
        return;
    }
    const TetLocation at = locator_->locateFrom(x, location);
    if (!at.found()) {
        location = -3 - at.exitPatch; // ≤ −2: outside, through patch −3 − location if ≥ 0
        out.velocity[i].setZero();
        if (needs.velocityGradient) out.velocityGradient[i].setZero();
        if (needs.turbulence) out.turbulentKineticEnergy[i] = out.dissipationRate[i] = 0;
        if (needs.temperature) out.temperature[i] = 0;
        if (needs.timeDerivative) out.velocityTimeDerivative[i].setZero();
        return;
    }
    location = at.tet;
    if (levels) return sampleLevelsAt(at, x, rotation, *levels, needs, out, i);
    const bool cellScheme = settings_.interpolation == FoamInterpolation::cell;
    const GasValues here = cellScheme ? gas_->cells[at.cell] : gas_->value(mesh_, at);
    out.velocity[i] = rotation * here.velocity;
    if (needs.velocityGradient) {
        const Mat3 gradient =
            cellScheme ? cellGradients_[at.cell] : tetGradient(mesh_, *locator_, *gas_, at);
        out.velocityGradient[i] =
            rotation * wedgeHoopGradient(gradient, here.velocity, x) * rotation.transpose();
    }
    if (needs.turbulence) {
        out.turbulentKineticEnergy[i] = here.scalars[0];
        out.dissipationRate[i] = here.scalars[1];
    }
    if (needs.temperature) out.temperature[i] = here.scalars[2];
}

void FoamCarrier::sample(std::span<const Vec3> points, double time, CarrierNeeds needs,
                         CarrierSample& out) const {
    std::vector<std::int32_t> locations(points.size(), -1);
    FoamCarrier::sampleFrom(points, locations, time, needs, out);
}

void FoamCarrier::sampleFrom(std::span<const Vec3> points, std::span<std::int32_t> locations,
                             double time, CarrierNeeds needs, CarrierSample& out) const {
    const auto has = [&](std::size_t s) { return series_ ? series_->has(s) : hasScalar_[s]; };
    if (needs.turbulence && !has(0)) missing("k");
    if (needs.turbulence && !has(1)) missing("epsilon");
    if (needs.temperature && !has(2)) missing("T");
    out.resize(points.size(), needs);
    std::optional<LevelCache<FoamLevel>::Pair> levels;
    if (series_) levels = series_->at(time);
    const auto count = static_cast<std::ptrdiff_t>(points.size());
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
    for (std::ptrdiff_t i = 0; i < count; ++i)
        sampleAt(points[i], locations[i], needs, out, static_cast<std::size_t>(i),
                 levels ? &*levels : nullptr);
}

std::optional<Box> FoamCarrier::bounds() const {
    Box box{mesh_.boundsMin, mesh_.boundsMax};
    if (wedge_) { // the wedge swept about its axis
        double lowest = INFINITY, highest = -INFINITY, radius = 0;
        for (const Vec3& point : mesh_.points) {
            const Vec3 d = point - wedge_->origin;
            const double axial = d.dot(wedge_->axis);
            lowest = std::min(lowest, axial);
            highest = std::max(highest, axial);
            radius = std::max(radius, (d - axial * wedge_->axis).norm());
        }
        const Vec3 a = wedge_->origin + lowest * wedge_->axis;
        const Vec3 b = wedge_->origin + highest * wedge_->axis;
        for (int j = 0; j < 3; ++j) {
            const double reach =
                radius * std::sqrt(std::max(0.0, 1 - wedge_->axis[j] * wedge_->axis[j]));
            box.min[j] = std::min(a[j], b[j]) - reach;
            box.max[j] = std::max(a[j], b[j]) + reach;
        }
    }
    return box;
}

std::optional<AxisymmetricFrame> FoamCarrier::axisymmetry() const {
    if (!wedge_) return std::nullopt;
    return AxisymmetricFrame{wedge_->origin, wedge_->axis, wedge_->radial, wedge_->angle};
}

std::vector<std::string> FoamCarrier::boundaryNames() const {
    std::vector<std::string> names;
    for (const auto& patch : mesh_.patches) names.push_back(patch.name);
    return names;
}

const FoamPatch& FoamCarrier::patchNamed(const std::string& name) const {
    const auto patch = std::find_if(mesh_.patches.begin(), mesh_.patches.end(),
                                    [&](const FoamPatch& p) { return p.name == name; });
    if (patch == mesh_.patches.end()) throw std::logic_error("no patch " + name + " in the mesh");
    return *patch;
}

std::vector<PatchTriangle> FoamCarrier::patchTriangles(const std::string& name) const {
    // Each face fanned about its point average, as the locator's tetrahedra split it, so the
    // triangles lie on the boundary the particles are tracked against. OpenFOAM orders a
    // boundary face's points counter-clockwise seen from outside: reversed, seen from the gas.
    const FoamPatch& patch = patchNamed(name);
    std::vector<PatchTriangle> triangles;
    for (int face = patch.start; face < patch.start + patch.size; ++face) {
        const auto points = mesh_.pointsOf(face);
        const Vec3& middle = locator_->faceMidpoint(face);
        for (std::size_t k = 0; k < points.size(); ++k)
            triangles.push_back(
                {middle, mesh_.points[points[(k + 1) % points.size()]], mesh_.points[points[k]]});
    }
    return triangles;
}

std::vector<std::int32_t> FoamCarrier::patchTriangleLocations(const std::string& name) const {
    // Triangle k of a face is the base of the owner's tetrahedron (cell, face, edge k).
    const FoamPatch& patch = patchNamed(name);
    std::vector<std::int32_t> locations;
    for (int face = patch.start; face < patch.start + patch.size; ++face) {
        const auto corners = static_cast<int>(mesh_.pointsOf(face).size());
        for (int edge = 0; edge < corners; ++edge)
            locations.push_back(locator_->tetIndex(mesh_.owner[face], face, edge));
    }
    return locations;
}

void FoamCarrier::holdInterval(double start, double end) const {
    if (series_) series_->hold(start, end);
}

CarrierNeeds FoamCarrier::provides() const {
    if (series_)
        return {.velocityGradient = true,
                .turbulence = series_->has(0) && series_->has(1),
                .temperature = series_->has(2),
                .timeDerivative = true};
    return {.velocityGradient = true,
            .turbulence = hasScalar_[0] && hasScalar_[1],
            .temperature = hasScalar_[2]};
}

double FoamCarrier::resolutionLength(std::int32_t location) const {
    if (lattice_) return lattice_->frame().spacing;
    if (location < 0 || location >= locator_->tetIndexEnd())
        return std::numeric_limits<double>::infinity();
    const int cell = locator_->tetAt(location).cell;
    const bool planar = wedge_ || emptyNormal_;
    double area = 0;
    for (const int face : mesh_.facesOf(cell)) {
        const int patch = mesh_.facePatch[face];
        if (planar && patch >= 0 &&
            (mesh_.patches[patch].type == PatchType::wedge ||
             mesh_.patches[patch].type == PatchType::empty))
            continue;
        area += mesh_.faceAreas[face].norm();
    }
    return (planar ? 4.0 : 6.0) * mesh_.cellVolumes[cell] / area;
}

std::string FoamCarrier::describe() const {
    std::string text =
        "foamField " +
        (series_ ? "series of " + std::to_string(series_->levelCount()) + " levels from "
                 : std::string()) +
        timeDirectory_.string() + " (" + std::to_string(mesh_.cellCount) + " cells, " +
        std::string(nameOf(foamInterpolationNames(), settings_.interpolation));
    if (wedge_) text += ", axisymmetric wedge";
    if (emptyNormal_) text += ", 2-D";
    if (lattice_) text += "; " + latticeReport_;
    return text + ")";
}

} // namespace slides
