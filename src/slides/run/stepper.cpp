#include "slides/run/stepper.h"

#include "slides/core/error.h"
#include "slides/core/parallel.h"
#include "slides/core/particle_order.h"
#include "slides/integrate/adaptive_runge_kutta_batch.h"
#include "slides/integrate/relaxation_batch.h"
#include "slides/physics/body_force.h"
#include "slides/surfaces/plane_contact.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <omp.h>
#include <span>
#include <sstream>
#include <stdexcept>

namespace slides {

Stepper::Stepper(const Scene& scene, const CarrierField& carrier, RankExchange* exchange)
    : scene_(scene),
      carrier_(carrier), drag_{scene.physics.drag, scene.fluid.density,
                               scene.fluid.kinematicViscosity, scene.particles.density},
      bodyAcceleration_(bodyAcceleration(scene.physics.gravity, scene.particles.density,
                                         scene.fluid.density, scene.physics.buoyancy)),
      injectors_(injectorsOf(scene), scene.collisions.model != CollisionModel::none),
      needs_(scene.physics.carrierNeeds()), dispersion_(scene.physics, scene.injection.seed),
      heating_(scene.physics.heatTransfer, scene.fluid, scene.particles, scene.time,
               scene.physics.historyAccuracy),
      surfaces_(scene.surfaces, scene.collisions, scene.deposition, scene.particles,
                scene.physics.heatTransfer, carrier) {
    if (!(scene.time.dt > 0))
        throw std::logic_error("time.dt is not set: the scene analysis chooses it "
                               "(analysis/scene_analysis.h)");
    if (scene.physics.unsteadyForces()) {
        std::vector<double> densities;
        for (const ParticleSpecies& species : scene.particles.allSpecies())
            densities.push_back(species.density);
        maxeyRiley_.emplace(scene.physics, scene.fluid, densities, scene.time, carrier.steady());
        cloud_.stateWidth = maxeyRiley_->stateWidth();
        if (maxeyRiley_->needs().velocityLaplacian && !carrier.provides().velocityLaplacian)
            throw std::logic_error("Faxén terms on a carrier without ∇²U: refused when the scene "
                                   "is read (config/scene_reader.cpp)");
    }
    // modelState: the Maxey–Riley step's block, then the heat transfer's.
    heating_.placeState(cloud_.stateWidth);
    cloud_.stateWidth += heating_.stateWidth();
    if (scene.physics.electromagnetic.on()) {
        if (maxeyRiley_)
            throw std::logic_error("electromagnetic forces with unsteady forces: refused when "
                                   "the scene is read (config/scene_reader.cpp)");
        chargedMotion_.emplace(scene.physics.electromagnetic, drag_, bodyAcceleration_,
                               scene.particles.susceptibility);
        if (scene.physics.electromagnetic.coulomb.on())
            coulomb_.emplace(scene.physics.electromagnetic.coulomb, scene.particles.density,
                             scene.domain);
    }
    if (scene.time.integrator == Integrator::adaptiveRungeKutta) {
        if (maxeyRiley_ || exchange)
            throw std::logic_error("adaptiveRungeKutta with unsteady forces, or in a parallel "
                                   "run: refused when the scene is read");
        cloud_.stateWidth = 1; // each particle's next trial sub-step [s]; 0: its step length
    }
    if (scene.collisions.model == CollisionModel::impulse)
        collisions_.emplace(scene.collisions, scene.particles);
    if (scene.collisions.model == CollisionModel::softSphere)
        softSpheres_.emplace(scene.collisions, scene.particles, scene.surfaces, scene.domain);
    tracksSpin_ = tracksSpin(scene.physics.spin, scene.collisions, scene.surfaces);
    exchange_ = exchange;
    if (exchange) injectors_.splitAmongRanks();
    plane_ = planeConstraintOf(carrier);
    for (const ParticleSpecies& species : scene.particles.species)
        speciesAccelerations_.push_back(bodyAcceleration(
            scene.physics.gravity, species.density, scene.fluid.density, scene.physics.buoyancy));
    cloud_.reserve(static_cast<std::size_t>(scene.particles.count));
    buildStages();
}

bool Stepper::finished() const {
    const double endTime = scene_.time.endTime;
    if (time_ >= endTime * (1 - 1e-12)) return true;
    return scene_.time.stopWhenAllDone && injectors_.finished() &&
           (exchange_ ? exchange_->everyRankEmpty(cloud_.size()) : cloud_.empty());
}

long Stepper::collisions() const {
    if (collisions_) return collisions_->collisions();
    return softSpheres_ ? softSpheres_->collisions() : 0;
}

RunCounters Stepper::counters() const {
    RunCounters counters{
        time_,           steps_,       injectors_.injected(), escaped_, particleSteps_,
        escapedThrough_, collisions(), surfaces_.rebounds(),  {}};
    if (injectors_.reinjects()) counters.reinjected = injectors_.reinjected();
    return counters;
}

RunSnapshot Stepper::snapshot() const {
    std::optional<long> listBuilds;
    if (softSpheres_) listBuilds = softSpheres_->listBuilds();
    std::optional<AdaptiveSteps> adaptiveSteps;
    if (scene_.time.integrator == Integrator::adaptiveRungeKutta) adaptiveSteps = adaptiveSteps_;
    return {counters(), cloud_, arrivals_, listBuilds, adaptiveSteps};
}

void Stepper::resume(const RunCounters& counters, ParticleCloud cloud,
                     std::vector<Arrival> arrivals, std::vector<ContactSpring> springs) {
    time_ = counters.time;
    steps_ = counters.steps;
    escaped_ = counters.escaped;
    escapedThrough_ = counters.escapedThrough;
    particleSteps_ = counters.particleSteps;
    injectors_.resumeAt(counters.time, counters.injected);
    injectors_.resumeReinjected(counters.reinjected);
    if (collisions_) collisions_->resume(counters.collisions);
    if (softSpheres_) softSpheres_->resume(counters.collisions, std::move(springs));
    surfaces_.resumeRebounds(counters.rebounds);
    if (cloud.stateWidth != cloud_.stateWidth)
        throw std::logic_error("checkpoint's model state does not fit the scene's models");
    cloud_ = std::move(cloud);
    if (exchange_) {
        cloud_.carrierLocation.assign(cloud_.size(), -1);
        for (auto* array : {&stepLengths_, &startTemperatures_, &gas_.temperature}) array->clear();
        startPositions_.clear();
        startVelocities_.clear();
        exchange_->keepHeldHere(cloud_, {stepLengths_, startPositions_, startVelocities_,
                                         startTemperatures_, gas_.temperature});
    }
    arrivals_ = std::move(arrivals);
    // The deposit is the particles that stuck: the arrivals at deposition surfaces.
    for (const Arrival& arrival : arrivals_)
        if (scene_.surfaces[static_cast<std::size_t>(arrival.surface)].interaction ==
            SurfaceInteraction::deposit)
            surfaces_.addToDeposit(arrival);
}

std::size_t Stepper::exitOf(std::size_t i) const {
    if (cloud_.carrierLocation.empty()) return 0;
    std::array<std::int32_t, 1> location{cloud_.carrierLocation[i]};
    // Left the box in this step (the mesh's, by default): and the mesh? (The exchange stage
    // has located every particle at its position already.)
    if (location[0] >= -1 && !exchange_) {
        CarrierSample scratch;
        carrier_.sampleFrom(std::array<Vec3, 1>{cloud_.position[i]}, location, time_, {}, scratch);
    }
    // Location −3 − p: outside the mesh, through patch p.
    return location[0] <= -3 ? static_cast<std::size_t>(-2 - location[0]) : 0;
}

void Stepper::step() {
    const double h = std::min(scene_.time.dt, scene_.time.endTime - time_);
    for (const Stage stage : stages_) (this->*stage)(h);
    time_ += h;
    ++steps_;
}

void Stepper::buildStages() {
    const bool gas = scene_.carrier.type != CarrierType::none;
    stages_.clear();
    if (gas && !carrier_.steady()) stages_.push_back(&Stepper::holdCarrierTimes);
    if (carrier_.keepsLocations() && !softSpheres_) stages_.push_back(&Stepper::orderInMemory);
    stages_.push_back(&Stepper::inject);
    if (softSpheres_) stages_.push_back(&Stepper::orderByContactCells);
    if (plane_) stages_.push_back(&Stepper::holdInPlane);
    if (!scene_.particles.alike()) stages_.push_back(&Stepper::holdSpeciesValues);
    if (softSpheres_) stages_.push_back(&Stepper::kickByContacts);
    if (coulomb_) stages_.push_back(&Stepper::kickByCoulombForces);
    // The paths' starts, for impulse collisions, heating and meeting surfaces at the touch.
    if (collisions_ || heating_.on() || surfaces_.meetsAtTouch())
        stages_.push_back(&Stepper::recordPathStarts);
    if (gas && samplesGasForAll()) stages_.push_back(&Stepper::sampleGas);
    if (gas && dispersion_.on()) stages_.push_back(&Stepper::disperse);
    if (plane_ && gas && dispersion_.on()) stages_.push_back(&Stepper::holdEddiesInPlane);
    stages_.push_back(gas ? &Stepper::advance : &Stepper::flyBallistically);
    if (plane_) stages_.push_back(&Stepper::holdInPlane);
    if (heating_.on()) stages_.push_back(&Stepper::heat);
    if (collisions_) stages_.push_back(&Stepper::collide);
    if (softSpheres_) stages_.push_back(&Stepper::kickByNewContacts);
    if (coulomb_) stages_.push_back(&Stepper::kickByCoulombForces);
    if (exchange_) stages_.push_back(&Stepper::exchangeAcrossRanks);
    stages_.push_back(&Stepper::meetSurfaces);
    // Contacts of particles in the plane act in it; a rebound off a surface may leave it.
    if (plane_) stages_.push_back(&Stepper::holdInPlane);
}

void Stepper::holdCarrierTimes(double h) { carrier_.holdInterval(time_, time_ + h); }

void Stepper::orderInMemory(double) { orderByLocation(cloud_, steps_); }

void Stepper::orderByContactCells(double) {
    if (steps_ % cellOrderInterval != 0) return;
    const std::vector<std::uint32_t> order = softSpheres_->cellOrder(cloud_);
    for (std::uint32_t k = 0; k < order.size(); ++k)
        if (order[k] != k) {
            reorderParticles(cloud_, order);
            reorderParticleArray(stepLengths_, order); // the new particles' remainders
            return;
        }
}

void Stepper::inject(double h) {
    const std::size_t alreadyInFlight = cloud_.size();
    injectors_.injectUntil(time_ + h, time_, carrier_, cloud_);
    // A particle injected at t_k inside the step flies only its remainder t + h − t_k.
    fillInParallel(stepLengths_, cloud_.size(), h);
    for (std::size_t i = alreadyInFlight; i < cloud_.size(); ++i)
        stepLengths_[i] = std::clamp(time_ + h - injectors_.injectionTime(cloud_.id[i]), 0.0, h);
    equipNewParticles(alreadyInFlight);
    particleSteps_ += cloud_.size();
}

void Stepper::equipNewParticles(std::size_t from) {
    if (carrier_.keepsLocations()) cloud_.carrierLocation.resize(cloud_.size(), -1);
    if (tracksSpin_) cloud_.angularVelocity.resize(cloud_.size(), Vec3::Zero());
    if (heating_.on())
        cloud_.temperature.resize(cloud_.size(), scene_.particles.injectionTemperature);
    if (chargedMotion_) chargedMotion_->charge(cloud_, from);
    injectors_.setStartStates(cloud_, from);
}

void Stepper::kickByContacts(double) {
    cloud_.contactForce.resize(cloud_.size(), Vec3::Zero());
    cloud_.contactTorque.resize(cloud_.size(), Vec3::Zero());
    softSpheres_->halfKick(cloud_, stepLengths_);
}

void Stepper::kickByCoulombForces(double) {
    coulomb_->evaluate(cloud_);
    coulomb_->halfKick(cloud_, stepLengths_, particleDensities_);
}

void Stepper::recordPathStarts(double) {
    copyInParallel(cloud_.position, startPositions_);
    copyInParallel(cloud_.velocity, startVelocities_);
}

void Stepper::heat(double) {
    startTemperatures_ = cloud_.temperature;
    startTemperatures_.resize(cloud_.size(), scene_.particles.injectionTemperature);
    heating_.advance(cloud_, gas_, startVelocities_, stepLengths_, speciesValues());
}

void Stepper::exchangeAcrossRanks(double) {
    // The step located every start where it sampled the gas there (sampleGas, or the midpoint
    // rule's own start sample).
    const bool startsLocated =
        scene_.carrier.type != CarrierType::none &&
        (samplesGasForAll() || scene_.time.integrator == Integrator::exponentialMidpoint);
    exchange_->exchange(
        cloud_,
        {stepLengths_, startPositions_, startVelocities_, startTemperatures_, gas_.temperature},
        startsLocated);
}

void Stepper::holdInPlane(double) { plane_->hold(cloud_); }

void Stepper::holdEddiesInPlane(double) { plane_->project(gas_.velocity); }

void Stepper::collide(double) { collisions_->collide(cloud_, startPositions_, stepLengths_); }

void Stepper::kickByNewContacts(double h) {
    softSpheres_->updateLoads(cloud_, h);
    softSpheres_->halfKick(cloud_, stepLengths_);
    const auto& wallContacts = softSpheres_->newWallContacts();
    for (std::size_t s = 0; s < wallContacts.size(); ++s)
        surfaces_.countRebounds(s, wallContacts[s]);
}

namespace {

/// One step of `scheme` (advanceExplicitly) over fraction × h_i for every
/// particle i with gas velocity u, the response time τ from the slip u − w (w = v, or the
/// midpoint velocity).
/// With differing species, particle i's density and body acceleration are density[i] and
/// acceleration[i] (else empty: the drag's and a).
template <typename Scheme>
void advanceEach(Scheme scheme, std::vector<Vec3>& x, std::vector<Vec3>& v,
                 const std::vector<Vec3>& u, const std::vector<Vec3>& w,
                 const std::vector<double>& radius, const DragParameters& drag, const Vec3& a,
                 const std::vector<double>& h, double fraction, const std::vector<double>& density,
                 const std::vector<Vec3>& acceleration) {
    const auto count = static_cast<std::ptrdiff_t>(x.size());
    if (!density.empty()) {
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
        for (std::ptrdiff_t i = 0; i < count; ++i) {
            const double tau =
                dragResponseTime(drag.withDensity(density[i]), radius[i], (u[i] - w[i]).norm());
            scheme(x[i], v[i], u[i], tau, acceleration[i], fraction * h[i]);
        }
        return;
    }
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
    for (std::ptrdiff_t i = 0; i < count; ++i) {
        const double tau = dragResponseTime(drag, radius[i], (u[i] - w[i]).norm());
        scheme(x[i], v[i], u[i], tau, a, fraction * h[i]);
    }
}

// The scheme as a function object, so advanceEach inlines it into its loop.
constexpr auto explicitStep = [](auto&&... step) { advanceExplicitly(step...); };

} // namespace

void Stepper::sampleGas(double) {
    CarrierNeeds needs = needs_;
    if (maxeyRiley_) needs.velocityGradient = maxeyRiley_->needs().velocityGradient;
    if (maxeyRiley_) needs.timeDerivative = maxeyRiley_->needs().timeDerivative;
    if (maxeyRiley_) needs.velocityLaplacian = maxeyRiley_->needs().velocityLaplacian;
    sampleCarrier(cloud_.position, cloud_.carrierLocation, time_, needs, gas_);
}

void Stepper::disperse(double) {
    dispersion_.perturb(cloud_, gas_, stepLengths_, drag_, bodyAcceleration_, speciesValues());
}

namespace {

/// A predicted point that left the mesh (location ≤ −2) has no gas there: its particle leaves
/// the mesh within the step and keeps the gas of its start (start entry startOffset + k) for
/// it, instead of the still gas outside, which would stop it short of the boundary for good.
void keepStartGasWhereOutside(std::span<const std::int32_t> locations, const CarrierSample& start,
                              std::size_t startOffset, CarrierSample& predicted) {
    for (std::size_t k = 0; k < locations.size(); ++k)
        if (locations[k] <= -2) predicted.copyEntry(k, start, startOffset + k);
}

} // namespace

void Stepper::advance(double h) {
    auto& x = cloud_.position;
    auto& v = cloud_.velocity;
    const auto& radius = cloud_.radius;
    if (maxeyRiley_) {
        // The predicted ends walk from the particles' cells and see the same eddies.
        midpointLocations_ = cloud_.carrierLocation;
        const auto sampleEnd = [&](const std::vector<Vec3>& points, CarrierSample& out) {
            sampleCarrier(points, midpointLocations_, time_ + h, maxeyRiley_->needs(), out);
            dispersion_.addTo(out.velocity, 0);
            if (plane_) plane_->project(out.velocity);
            keepStartGasWhereOutside(midpointLocations_, gas_, 0, out);
        };
        return maxeyRiley_->advance(cloud_, gas_, sampleEnd, stepLengths_, particleSpecies_,
                                    particleDensities_);
    }
    if (chargedMotion_ && scene_.time.integrator != Integrator::adaptiveRungeKutta) {
        midpointLocations_ = cloud_.carrierLocation;
        const auto sampleMidpoint = [&](const std::vector<Vec3>& points, CarrierSample& out) {
            sampleCarrier(points, midpointLocations_, time_ + 0.5 * h, CarrierNeeds{}, out);
            dispersion_.addTo(out.velocity, 0);
            if (plane_) plane_->project(out.velocity);
            keepStartGasWhereOutside(midpointLocations_, gas_, 0, out);
        };
        return chargedMotion_->advance(cloud_, gas_, sampleMidpoint, stepLengths_, speciesValues());
    }
    const auto& u = gas_.velocity;
    const Vec3& a = bodyAcceleration_;

    switch (scene_.time.integrator) {
    case Integrator::explicitEuler:
        advanceEach(explicitStep, x, v, u, v, radius, drag_, a, stepLengths_, 1.0,
                    particleDensities_, particleAccelerations_);
        break;
    case Integrator::exponentialEuler:
        relaxBatchExactly(
            {x, v, x, v, u, v, radius, stepLengths_, particleDensities_, particleAccelerations_},
            drag_, a, 1.0);
        break;
    case Integrator::exponentialMidpoint: advanceByMidpointRule(h); break;
    case Integrator::adaptiveRungeKutta: advanceAdaptively(h); break;
    }
}

bool Stepper::samplesGasForAll() const {
    const bool adaptive = scene_.time.integrator == Integrator::adaptiveRungeKutta;
    return maxeyRiley_ || (chargedMotion_ && !adaptive) || dispersion_.on() || heating_.on() ||
           scene_.time.integrator == Integrator::explicitEuler ||
           scene_.time.integrator == Integrator::exponentialEuler;
}

void Stepper::advanceByMidpointRule(double h) {
    // Exponential midpoint rule: predict to t + h/2 with the state at t, sample the carrier at
    // the predicted points, then take the whole step from the state at t with u and τ frozen at
    // their midpoint values (second order). Block by block, so the samples and the prediction
    // stay in the core's cache; the start sample is the stage's one (gas_) when another stage
    // needs it too, else the block's own.
    // A parallel run's carrier samples collectively (run/rank_carrier.h): every rank makes the
    // same calls, so there the cloud is one block on one thread, empty or not.
    const std::size_t count = cloud_.size();
    const std::size_t block = exchange_ ? std::max<std::size_t>(count, 1) : samplingBlock;
    const auto blocks = static_cast<std::ptrdiff_t>(exchange_ ? 1 : (count + block - 1) / block);
    const bool keepsLocations = carrier_.keepsLocations();
    const bool sampled = samplesGasForAll();
    const bool parallel = !exchange_ && static_cast<std::ptrdiff_t>(count) >= minimumParallelBatch;
    midpointScratch_.resize(
        std::max(midpointScratch_.size(), static_cast<std::size_t>(omp_get_max_threads())));
#pragma omp parallel for schedule(dynamic) if (parallel)
    for (std::ptrdiff_t b = 0; b < blocks; ++b) {
        MidpointScratch& scratch = midpointScratch_[static_cast<std::size_t>(omp_get_thread_num())];
        const std::size_t first = static_cast<std::size_t>(b) * block;
        const std::size_t n = std::min(block, count - first);
        const std::span x(cloud_.position.data() + first, n);
        const std::span v(cloud_.velocity.data() + first, n);
        const std::span radius(cloud_.radius.data() + first, n);
        const std::span stepLength(stepLengths_.data() + first, n);
        std::span<std::int32_t> locations;
        if (keepsLocations) locations = {cloud_.carrierLocation.data() + first, n};
        if (!sampled) sampleCarrier(x, locations, time_, CarrierNeeds{}, scratch.gas);
        const std::span<const Vec3> u =
            sampled ? std::span<const Vec3>(gas_.velocity.data() + first, n) : scratch.gas.velocity;
        scratch.position.resize(n);
        scratch.velocity.resize(n);
        std::span<const double> density;
        std::span<const Vec3> acceleration;
        if (!particleDensities_.empty()) {
            density = {particleDensities_.data() + first, n};
            acceleration = {particleAccelerations_.data() + first, n};
        }
        relaxBatchExactly({x, v, scratch.position, scratch.velocity, u, v, radius, stepLength,
                           density, acceleration},
                          drag_, bodyAcceleration_, 0.5);
        scratch.locations.assign(locations.begin(), locations.end());
        sampleCarrier(scratch.position, scratch.locations, time_ + 0.5 * h, CarrierNeeds{},
                      scratch.midpointGas);
        dispersion_.addTo(scratch.midpointGas.velocity, first);
        if (plane_) plane_->project(scratch.midpointGas.velocity);
        if (keepsLocations)
            keepStartGasWhereOutside(scratch.locations, sampled ? gas_ : scratch.gas,
                                     sampled ? first : 0, scratch.midpointGas);
        relaxBatchExactly({x, v, x, v, scratch.midpointGas.velocity, scratch.velocity, radius,
                           stepLength, density, acceleration},
                          drag_, bodyAcceleration_, 1.0);
    }
}

void Stepper::advanceAdaptively(double h) {
    // Blocks of the cloud on the threads: a particle's sub-steps do not depend on its block
    // (integrate/adaptive_runge_kutta_batch.h), so the result is the same at any thread count.
    // The carrier is sampled at the step's middle time: exact for a frozen one, second order in
    // dt for an unsteady one (as the midpoint rule's second sample). The eddy
    // fluctuations of this step (stage 2b) are held over it, as the other schemes hold them; the
    // Lorentz force of charged particles joins the right-hand side.
    const std::size_t count = cloud_.size();
    if (dispersion_.on()) {
        eddyVelocities_.assign(count, Vec3::Zero());
        dispersion_.addTo(eddyVelocities_, 0);
        if (plane_) plane_->project(eddyVelocities_);
    }
    if (chargedMotion_) {
        lorentzRates_.resize(count);
        for (std::size_t i = 0; i < count; ++i)
            lorentzRates_[i] = chargedMotion_->ratesOf(cloud_, i, speciesValues());
    }
    const auto blocks = static_cast<std::ptrdiff_t>((count + samplingBlock - 1) / samplingBlock);
    long attempted = 0, rejected = 0;
#pragma omp parallel for schedule(dynamic) reduction(+ : attempted, rejected) if (            \
        static_cast<std::ptrdiff_t>(count) >= minimumParallelBatch)
    for (std::ptrdiff_t b = 0; b < blocks; ++b) {
        const std::size_t first = static_cast<std::size_t>(b) * samplingBlock;
        const std::size_t n = std::min(samplingBlock, count - first);
        AdaptiveBatch batch{.position = {cloud_.position.data() + first, n},
                            .velocity = {cloud_.velocity.data() + first, n},
                            .radius = {cloud_.radius.data() + first, n},
                            .stepLength = {stepLengths_.data() + first, n},
                            .trialStep = {cloud_.modelState.data() + first, n}};
        if (dispersion_.on()) batch.eddyVelocity = {eddyVelocities_.data() + first, n};
        if (chargedMotion_) batch.lorentz = {lorentzRates_.data() + first, n};
        if (!particleDensities_.empty()) {
            batch.density = {particleDensities_.data() + first, n};
            batch.acceleration = {particleAccelerations_.data() + first, n};
        }
        if (carrier_.keepsLocations()) batch.locations = {cloud_.carrierLocation.data() + first, n};
        const AdaptiveSteps steps = advanceAdaptiveBatch(
            batch, time_ + 0.5 * h, scene_.time.tolerance, drag_, bodyAcceleration_, carrier_);
        attempted += steps.attempted;
        rejected += steps.rejected;
    }
    adaptiveSteps_ += {attempted, rejected};
}

void Stepper::holdSpeciesValues(double) {
    const ParticleSettings& particles = scene_.particles;
    const std::size_t count = cloud_.size();
    particleSpecies_.resize(count);
    particleDensities_.resize(count);
    particleAccelerations_.resize(count);
    if (heating_.on()) particleSpecificHeats_.resize(count);
    const bool magnetisable = scene_.physics.electromagnetic.magnetisable();
    if (magnetisable) particleSusceptibilities_.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        particleSpecies_[i] = particles.speciesOf(cloud_.id[i]);
        const auto species = static_cast<std::size_t>(particleSpecies_[i]);
        particleDensities_[i] = particles.species[species].density;
        particleAccelerations_[i] = speciesAccelerations_[species];
        if (heating_.on()) particleSpecificHeats_[i] = particles.species[species].specificHeat;
        if (magnetisable) particleSusceptibilities_[i] = particles.species[species].susceptibility;
    }
}

SpeciesValues Stepper::speciesValues() const {
    return {particleDensities_, particleAccelerations_, particleSpecificHeats_,
            particleSusceptibilities_};
}

void Stepper::flyBallistically(double) {
    if (chargedMotion_) return chargedMotion_->fly(cloud_, stepLengths_, speciesValues());
    const auto count = static_cast<std::ptrdiff_t>(cloud_.size());
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
    for (std::ptrdiff_t i = 0; i < count; ++i) {
        const Vec3& a =
            particleAccelerations_.empty() ? bodyAcceleration_ : particleAccelerations_[i];
        const double h = stepLengths_[i];
        cloud_.position[i] += (cloud_.velocity[i] + 0.5 * h * a) * h; // exact for constant a
        cloud_.velocity[i] += h * a;
    }
}

void Stepper::sampleCarrier(std::span<const Vec3> points, std::span<std::int32_t> locations,
                            double time, CarrierNeeds needs, CarrierSample& out) const {
    if (carrier_.keepsLocations())
        carrier_.sampleFrom(points, locations, time, needs, out);
    else
        carrier_.sample(points, time, needs, out);
}

std::optional<StepTemperature> Stepper::temperatureOver(std::size_t i) const {
    if (!heating_.on()) return std::nullopt;
    return StepTemperature{startTemperatures_[i], gas_.temperature[i]};
}

void Stepper::meetSurfaces(double h) {
    if (!surfaces_.meetsAtTouch()) {
        // Nothing to meet: only a particle that is not finite or has left the box needs the
        // loop below, and a parallel look finds whether there is one.
        const auto count = static_cast<std::ptrdiff_t>(cloud_.size());
        bool attention = false;
#pragma omp parallel for schedule(static)                                                          \
    reduction(||                                                                                   \
              : attention) if (count >= minimumParallelSweep)
        for (std::ptrdiff_t i = 0; i < count; ++i)
            attention = attention || !cloud_.position[i].allFinite() ||
                        !cloud_.velocity[i].allFinite() ||
                        !insideBox(scene_.domain, cloud_.position[i]) ||
                        (!cloud_.carrierLocation.empty() && cloud_.carrierLocation[i] < -1);
        if (!attention) return;
    }
    surfaces_.indexDeposit();
    // In parallel, the particles that only fly on: finite, in the box and the mesh, their path
    // touching no surface; the rest are met one by one in order (arrivals, deposit, removal).
    const auto count = static_cast<std::ptrdiff_t>(cloud_.size());
    fliesOn_.resize(cloud_.size());
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
    for (std::ptrdiff_t n = 0; n < count; ++n) {
        const auto i = static_cast<std::size_t>(n);
        const Vec3& x = cloud_.position[i];
        fliesOn_[i] = x.allFinite() && cloud_.velocity[i].allFinite() &&
                      insideBox(scene_.domain, x) &&
                      (cloud_.carrierLocation.empty() || cloud_.carrierLocation[i] >= -1) &&
                      (!surfaces_.meetsAtTouch() ||
                       !surfaces_.mayTouch(startPositions_[i], x, cloud_.radius[i]));
    }
    // Backwards, so the particle swapped into a removed slot has already been handled.
    for (std::size_t i = cloud_.size(); i-- > 0;) {
        if (fliesOn_[i]) continue;
        const Vec3& x = cloud_.position[i];
        const Vec3& v = cloud_.velocity[i];
        if (!x.allFinite() || !v.allFinite()) {
            std::ostringstream message;
            message << "particle " << cloud_.id[i]
                    << " reached a non-finite state at t = " << time_ + h << " s (position "
                    << x.transpose() << ", velocity " << v.transpose()
                    << "): its forces overflowed or the step is unstable; compare time.dt "
                       "with the step the scene analysis suggests";
            throw NonFiniteState(message.str());
        }
        Arrival arrival;
        const ImpactResult impact =
            surfaces_.meetsAtTouch()
                ? surfaces_.meet(cloud_, i, startPositions_[i], startVelocities_[i],
                                 stepLengths_[i], time_ + h, temperatureOver(i), arrival)
                : ImpactResult::none;
        if (impact == ImpactResult::arrived) {
            arrivals_.push_back(arrival);
        } else if (insideBox(scene_.domain, cloud_.position[i]) &&
                   (cloud_.carrierLocation.empty() || cloud_.carrierLocation[i] >= -1)) {
            continue; // a location below −1 left the mesh at the step's start
        } else {
            ++escaped_;
            const std::size_t exit = exitOf(i);
            if (escapedThrough_.size() <= exit) escapedThrough_.resize(exit + 1, 0);
            ++escapedThrough_[exit];
            injectors_.noteEscape(cloud_.id[i]);
        }
        cloud_.removeAt(i); // swaps in the last particle, already handled
    }
    // Constant mass flow: the escaped particles' replacements enter at the step's end.
    const std::size_t inFlight = cloud_.size();
    if (injectors_.reinjectEscaped(time_ + h, carrier_, cloud_) > 0) equipNewParticles(inFlight);
}

} // namespace slides
