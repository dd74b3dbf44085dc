#include "slides/integrate/injector.h"

#include "slides/core/parallel.h"
#include "slides/core/random.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace slides {

Vec3 latticeSite(const InjectionSettings& injection, ParticleId id) {
    const auto& sites = injection.latticeSites;
    const auto nx = static_cast<ParticleId>(sites[0]), ny = static_cast<ParticleId>(sites[1]);
    const Vec3 cell(static_cast<double>(id % nx), static_cast<double>(id / nx % ny),
                    static_cast<double>(id / (nx * ny)));
    return injection.latticeOrigin + injection.latticeSpacing * (cell.array() + 0.5).matrix();
}

Vec3 coneDirection(const ConeSettings& cone, const Vec3& axis, const Vec3& across,
                   double uniformPolar, double uniformAzimuth) {
    // Uniform on the band of the sphere: its area element is d(cos θ) dφ.
    const double cosInner = std::cos(cone.innerHalfAngle), cosOuter = std::cos(cone.outerHalfAngle);
    const double cosPolar = cosOuter + uniformPolar * (cosInner - cosOuter);
    const double sinPolar = std::sqrt(std::max(0.0, 1 - cosPolar * cosPolar));
    const double azimuth = 2.0 * std::numbers::pi * uniformAzimuth;
    const Vec3 other = axis.cross(across);
    return cosPolar * axis + sinPolar * (std::cos(azimuth) * across + std::sin(azimuth) * other);
}

Injector::Injector(const InjectionSettings& injection, const JetNozzle& nozzle,
                   const ParticleSettings& particles)
    : Injector(singleInjector(injection, nozzle, particles)) {}

Injector::Injector(const InjectorSettings& settings, bool avoidOverlap)
    : settings_(settings), radius_(settings.radius),
      startsAtGasVelocity_(settings.model == InjectionModel::disc),
      startsAtNormalGasVelocity_(settings.model == InjectionModel::patch &&
                                 !settings.patch.velocity),
      avoidOverlap_(avoidOverlap && !settings.givesRows() &&
                    settings.injection.mode != InjectionMode::lattice) {}

double Injector::injectionTime(ParticleId id) const {
    const auto k = id - settings_.firstId;
    const double start = settings_.startTime;
    if (settings_.givesRows()) return start + settings_.rows[k].time;
    return settings_.injection.mode == InjectionMode::rate
               ? start + static_cast<double>(k) / settings_.injection.rate
               : start;
}

long Injector::dueBefore(double until) const {
    long due = 0;
    while (due < settings_.count &&
           injectionTime(settings_.firstId + static_cast<ParticleId>(due)) < until)
        ++due;
    return due;
}

Injector::Start Injector::drawStart(ParticleId id, std::uint32_t attempt) const {
    const InjectorSettings& settings = settings_;
    if (settings.givesRows()) {
        const ParticleRow& row = settings.rows[id - settings.firstId];
        return {row.position, row.velocity, Vec3::Zero()};
    }
    const InjectionSettings& injection = settings.injection;
    RandomStream random(injection.seed, id, RandomPurpose::injection, attempt);
    if (injection.mode == InjectionMode::lattice) {
        Vec3 added;
        const double spread = injection.latticeVelocitySpread;
        for (int axis = 0; axis < 3; ++axis) added[axis] = spread * (2 * random.uniform() - 1);
        return {latticeSite(injection, id), added, Vec3::Zero()};
    }
    if (settings.model == InjectionModel::patch) {
        const double uniformArea = random.uniform(), u1 = random.uniform(), u2 = random.uniform();
        const double uniformTurn = patch_->swept() ? random.uniform() : 0.0;
        const PatchSampler::Point point = patch_->draw(uniformArea, u1, u2, uniformTurn);
        // On a wedge a given velocity turns with the point: it is the wedge's, swept.
        return {point.position, point.turn * settings.patch.velocity.value_or(Vec3::Zero()),
                point.normal, patchLocations_.empty() ? -1 : patchLocations_[point.triangle]};
    }
    const JetNozzle& nozzle = settings.nozzle;
    const Vec3 across = nozzle.crossSpanDirection;
    const Vec3 other = nozzle.axis.cross(across);
    const double radialFraction = std::sqrt(random.uniform()); // uniform in disc area
    const double angle = 2.0 * std::numbers::pi * random.uniform();
    const double direction = 2.0 * std::numbers::pi * random.uniform();
    const Vec3 position = nozzle.centre + nozzle.radius * radialFraction *
                                              (std::cos(angle) * across + std::sin(angle) * other);
    if (settings.model == InjectionModel::disc)
        return {position,
                injection.crossSpanSpeed *
                    (std::cos(direction) * across + std::sin(direction) * other),
                Vec3::Zero()};
    // Cone: the polar angle from a fresh uniform, the azimuth from `direction`'s.
    const ConeSettings& cone = settings.cone;
    const double polar = random.uniform();
    const double speed = cone.speed + cone.speedDeviation * random.normal();
    return {position,
            speed * coneDirection(cone, nozzle.axis, across, polar,
                                  direction / (2.0 * std::numbers::pi)),
            Vec3::Zero()};
}

void Injector::setStartStates(ParticleCloud& cloud, std::size_t from) const {
    if (!settings_.rowsGiveSpin && !settings_.rowsGiveTemperature) return;
    for (std::size_t i = from; i < cloud.size(); ++i) {
        if (!owns(cloud.id[i])) continue;
        const ParticleRow& row = settings_.rows[cloud.id[i] - settings_.firstId];
        if (settings_.rowsGiveSpin && i < cloud.angularVelocity.size())
            cloud.angularVelocity[i] = row.angularVelocity;
        if (settings_.rowsGiveTemperature && i < cloud.temperature.size())
            cloud.temperature[i] = row.temperature;
    }
}

void Injector::drawStarts(std::span<const ParticleId> ids, const ParticleCloud& cloud) {
    const std::size_t count = ids.size();
    positions_.resize(count);
    addedVelocities_.resize(count);
    patchNormals_.resize(startsAtNormalGasVelocity_ ? count : 0);
    locations_.resize(count);
    const auto keep = [&](std::size_t k, const Start& start) {
        positions_[k] = start.position;
        addedVelocities_[k] = start.addedVelocity;
        if (startsAtNormalGasVelocity_) patchNormals_[k] = start.patchNormal;
        locations_[k] = start.location;
    };
    if (!avoidOverlap_) {
        // Each draw is keyed by its particle's id: the same on any thread.
        const auto n = static_cast<std::ptrdiff_t>(count);
#pragma omp parallel for schedule(static) if (n >= minimumParallelBatch)
        for (std::ptrdiff_t k = 0; k < n; ++k)
            keep(static_cast<std::size_t>(k), drawStart(ids[static_cast<std::size_t>(k)], 0));
        return;
    }
    constexpr std::uint32_t attempts = 64;
    const double newest = *std::max_element(radii_.begin(), radii_.end());
    const double largest = std::max(
        newest,
        cloud.radius.empty() ? 0.0 : *std::max_element(cloud.radius.begin(), cloud.radius.end()));
    nearby_->gather(cloud, startBounds(), newest + largest, count);
    for (std::size_t k = 0; k < count; ++k) {
        for (std::uint32_t attempt = 0; attempt < attempts; ++attempt) {
            keep(k, drawStart(ids[k], attempt));
            if (!nearby_->overlaps(positions_[k], radii_[k])) break;
        }
        nearby_->add(positions_[k], radii_[k]);
    }
}

Box Injector::startBounds() const {
    if (settings_.model == InjectionModel::patch) return patch_->bounds();
    // The disc: its rim reaches R √(1 − axisᵢ²) along axis i from its centre.
    const JetNozzle& nozzle = settings_.nozzle;
    const Vec3 rim =
        nozzle.radius * (1 - nozzle.axis.array().square()).cwiseMax(0.0).sqrt().matrix();
    return {nozzle.centre - rim, nozzle.centre + rim};
}

void Injector::injectUntil(double until, double time, const CarrierField& carrier,
                           ParticleCloud& cloud) {
    const long first = injected_;
    long last = first;
    while (last < settings_.count &&
           injectionTime(settings_.firstId + static_cast<ParticleId>(last)) < until)
        ++last;
    if (last == first) return;
    ids_.resize(static_cast<std::size_t>(last - first));
    std::iota(ids_.begin(), ids_.end(), settings_.firstId + static_cast<ParticleId>(first));
    add(ids_, time, carrier, cloud);
    injected_ = last;
    // The batches' scratch goes once the last is in: a run injecting all at its start would
    // keep about 80 B a particle in it. (Assigning {} would keep the capacity.) An injector
    // that re-injects keeps it for the replacements.
    if (finished() && !settings_.injection.reinjectEscaped) {
        ids_ = std::vector<ParticleId>();
        positions_ = std::vector<Vec3>();
        addedVelocities_ = std::vector<Vec3>();
        patchNormals_ = std::vector<Vec3>();
        radii_ = std::vector<double>();
        addedIds_ = std::vector<ParticleId>();
        locations_ = std::vector<std::int32_t>();
        keep_ = std::vector<std::uint8_t>();
        nearby_.reset();
        gas_ = CarrierSample{};
    }
}

void Injector::reinject(std::span<const ParticleId> ids, double time, const CarrierField& carrier,
                        ParticleCloud& cloud) {
    if (!ids.empty()) add(ids, time, carrier, cloud);
}

void Injector::leaveToOtherRanks(std::span<const ParticleId> ids, const CarrierField& carrier) {
    keep_.assign(ids.size(), 1);
    // Whether a start is searched for is alike on every rank: every start of a batch is drawn
    // on a patch triangle whose tetrahedron is known, or none is.
    const bool searched = std::ranges::find(locations_, -1) != locations_.end();
    if (splitAmongRanks_ && searched) {
        carrier.keepHeldHere(positions_, locations_, keep_);
    } else {
        for (std::size_t k = 0; k < ids.size(); ++k) {
            if (locations_[k] != CarrierField::heldElsewhere) continue;
            if (splitAmongRanks_)
                keep_[k] = 0;
            else
                locations_[k] = -1;
        }
    }
    addedIds_.clear();
    for (std::size_t k = 0; k < ids.size(); ++k) {
        if (!keep_[k]) continue;
        const std::size_t n = addedIds_.size();
        addedIds_.push_back(ids[k]);
        positions_[n] = positions_[k];
        addedVelocities_[n] = addedVelocities_[k];
        if (startsAtNormalGasVelocity_) patchNormals_[n] = patchNormals_[k];
        radii_[n] = radii_[k];
        locations_[n] = locations_[k];
    }
    const std::size_t n = addedIds_.size();
    positions_.resize(n);
    addedVelocities_.resize(n);
    if (startsAtNormalGasVelocity_) patchNormals_.resize(n);
    radii_.resize(n);
    locations_.resize(n);
}

void Injector::add(std::span<const ParticleId> ids, double time, const CarrierField& carrier,
                   ParticleCloud& cloud) {
    if (settings_.model == InjectionModel::patch && !patch_) {
        patch_.emplace(carrier.patchTriangles(settings_.patch.name), carrier.axisymmetry());
        // A point drawn on a triangle lies in the tetrahedron behind it, unless it is then
        // turned about a wedge's axis.
        if (!patch_->swept())
            patchLocations_ = carrier.patchTriangleLocations(settings_.patch.name);
    }
    if (avoidOverlap_ && !nearby_) nearby_.emplace(planeConstraintOf(carrier));
    const std::size_t count = ids.size();
    radii_.resize(count);
    const auto n = static_cast<std::ptrdiff_t>(count);
#pragma omp parallel for schedule(static) if (n >= minimumParallelBatch)
    for (std::ptrdiff_t k = 0; k < n; ++k) {
        const ParticleId id = ids[static_cast<std::size_t>(k)];
        radii_[static_cast<std::size_t>(k)] = settings_.givesRows()
                                                  ? settings_.rows[id - settings_.firstId].radius
                                                  : radius_.draw(settings_.injection.seed, id);
    }
    drawStarts(ids, cloud);
    leaveToOtherRanks(ids, carrier);
    if (carrier.keepsLocations()) {
        // A mesh carrier's location of each start, which the cloud keeps so that the first step
        // walks from there: the tetrahedron behind its patch triangle, else searched for.
        carrier.sampleFrom(positions_, locations_, time, CarrierNeeds{}, gas_);
        cloud.carrierLocation.resize(cloud.size(), -1);
    } else if (startsAtGasVelocity_ || startsAtNormalGasVelocity_) {
        carrier.sample(positions_, time, CarrierNeeds{}, gas_);
    }
    for (std::size_t k = 0; k < addedIds_.size(); ++k) {
        Vec3 velocity = addedVelocities_[k];
        if (startsAtGasVelocity_) velocity += gas_.velocity[k];
        if (startsAtNormalGasVelocity_)
            velocity = gas_.velocity[k].dot(patchNormals_[k]) * patchNormals_[k];
        cloud.add(addedIds_[k], positions_[k], velocity, radii_[k]);
        if (carrier.keepsLocations()) cloud.carrierLocation.push_back(locations_[k]);
    }
}

} // namespace slides
