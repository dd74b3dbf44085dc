#include "slides/analysis/scene_analysis.h"

#include "slides/analysis/term_estimates.h"
#include "slides/core/name_table.h"
#include "slides/integrate/patch_sampler.h"
#include "slides/physics/dispersion.h"
#include "slides/physics/drag.h"
#include "slides/physics/heat_transfer.h"
#include "slides/physics/lift.h"
#include "slides/physics/soft_contact.h"
#include "slides/physics/spin.h"
#include "slides/physics/unsteady.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>

namespace slides {

namespace {

constexpr double notANumber = std::numeric_limits<double>::quiet_NaN();

/// Positive values binned on a log scale, 32 bins a decade from 1e-15 to 1e15: percentiles of
/// many path points in constant memory, to a bin (7 %).
class LogHistogram {
public:
    void add(double value) {
        if (!(value > 0) || !std::isfinite(value)) return;
        const int bin = static_cast<int>((std::log10(value) + 15) * binsPerDecade);
        ++counts_[static_cast<std::size_t>(std::clamp(bin, 0, binCount - 1))];
        ++total_;
    }
    /// The q-quantile, NaN when empty.
    double quantile(double q) const {
        if (total_ == 0) return notANumber;
        const double wanted = q * static_cast<double>(total_);
        double cumulative = 0;
        for (int bin = 0; bin < binCount; ++bin) {
            cumulative += static_cast<double>(counts_[static_cast<std::size_t>(bin)]);
            if (cumulative >= wanted && cumulative > 0)
                return std::pow(10.0, (bin + 0.5) / binsPerDecade - 15);
        }
        return std::pow(10.0, 15.0);
    }

private:
    static constexpr int binsPerDecade = 32;
    static constexpr int binCount = 30 * binsPerDecade;
    std::array<std::uint64_t, binCount> counts_{};
    std::uint64_t total_ = 0;
};

/// The force terms estimated by the deviation they drive (term_estimates.h).
enum ForceTerm { pressureGradientForce, addedMassForce, shearLiftForce, spinLiftForce, forceTerms };

/// The force row of a term estimated by its deviation.
ForceTerm forceOf(PhysicsTerm term) {
    switch (term) {
    case PhysicsTerm::addedMass: return addedMassForce;
    case PhysicsTerm::pressureGradient: return pressureGradientForce;
    case PhysicsTerm::shearLift: return shearLiftForce;
    default: return spinLiftForce;
    }
}

/// One pilot particle's estimates so far, and its slip path for the Basset integral.
struct Track {
    std::array<Vec3, forceTerms> deviation{Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    Vec3 spin = Vec3::Zero();
    double temperature = 0;
    double radius = 0;
    // The slip path, decimated to at most maxSlipSamples points (every stride-th point kept).
    std::vector<double> times;
    std::vector<Vec3> slips;
    std::vector<double> responseTimes;
    long stride = 1;
    long sinceKept = 0;
};

constexpr std::size_t maxSlipSamples = 1024;

/// Accumulates the estimates over the pilot's steps.
class PathEstimator {
public:
    PathEstimator(const Scene& scene, const CarrierField& carrier)
        : scene_(scene), drag_{scene.physics.drag, scene.fluid.density,
                               scene.fluid.kinematicViscosity, scene.particles.density} {
        // Each injector sprays through its disc, or the faces of its patch.
        for (const InjectorSettings& injector : injectorsOf(scene))
            patchAreas_.push_back(injector.model == InjectionModel::patch
                                      ? PatchSampler(carrier.patchTriangles(injector.patch.name),
                                                     carrier.axisymmetry())
                                            .area()
                                      : 0.0);
        const FluidSettings& fluid = scene.fluid;
        densityRatio_ = fluid.density / scene.particles.density;
        prandtl_ = prandtlNumber(fluid.density, fluid.kinematicViscosity, fluid.specificHeat,
                                 fluid.thermalConductivity);
    }

    void operator()(const PilotStep& step) {
        for (const PathPoint& point : step.points) visitPoint(point, step);
        visitCloud(step);
        for (const ParticleId id : step.ended) endPath(id, step.time);
    }

    /// Ends the paths still in flight.
    void finish(double time) {
        std::vector<ParticleId> open;
        for (const auto& [id, track] : tracks_) open.push_back(id);
        for (const ParticleId id : open) endPath(id, time);
    }

    void decide(SceneAnalysis& analysis, const CarrierField& carrier) const;
    void limitTimeStep(SceneAnalysis& analysis, const Scene& resolved) const;
    void fillFigures(SceneFigures& figures) const;

private:
    void visitPoint(const PathPoint& point, const PilotStep& step);
    void visitCloud(const PilotStep& step);
    void endPath(ParticleId id, double time);

    const Scene& scene_;
    DragParameters drag_;
    std::vector<double> patchAreas_; ///< by injector: its patch's area [m²], 0 for a disc
    double densityRatio_ = 0;
    double prandtl_ = 0;
    std::map<ParticleId, Track> tracks_;

    double referenceSpeed_ = 0;
    std::array<double, forceTerms> largestDeviation_{};
    std::array<double, forceTerms + 1> peakToDrag_{}; ///< the forces, then history
    double largestHistoryDeviation_ = 0;
    double largestFluctuation_ = 0;
    double largestTemperatureChange_ = 0;
    double largestThermalRatio_ = 0; ///< τ/τ_θ
    double largestBiot_ = 0;
    double reynoldsMin_ = INFINITY, reynoldsMax_ = 0;
    double responseTimeMin_ = INFINITY, responseTimeMax_ = 0;
    double radiusMin_ = INFINITY, radiusMax_ = 0;
    std::vector<double> flightTimes_;
    // Collisions: the spray's number density along the flight, from the pilot cloud's spread.
    double initialSpread_ = 0, initialSpeed_ = 0;
    double expectedCollisions_ = 0, largestCollisionRate_ = 0;
    double collisionVelocityChange_ = 0; ///< Σ collisions × relative speed [m/s]
    double volumeFractionNozzle_ = 0, volumeFractionMax_ = 0;
    // Time-step limits, per path point.
    LogHistogram flowSteps_;     ///< the flow limit [s]
    LogHistogram crossingSteps_; ///< the cell-crossing limit [s]
    LogHistogram responseTimes_; ///< [s]
    LogHistogram eddyTimes_;     ///< T_L [s]
};

void PathEstimator::visitPoint(const PathPoint& point, const PilotStep& step) {
    const FluidSettings& fluid = scene_.fluid;
    const double radius = point.radius;
    const double rhoP = scene_.particles.density;
    Track& track = tracks_[point.id];
    if (track.times.empty()) { // released with this slip at the start (pilot: all at t = 0)
        track.radius = radius;
        track.temperature = scene_.particles.injectionTemperature;
        track.times.push_back(0);
        track.slips.push_back(point.gasVelocity - point.velocity);
        track.responseTimes.push_back(dragResponseTime(drag_, radius, track.slips[0].norm()));
    }
    const Vec3 slip = point.gasVelocity - point.velocity;
    const double slipSpeed = slip.norm();
    const double tau = dragResponseTime(drag_, radius, slipSpeed);
    const double reynolds = particleReynolds(slipSpeed, radius, fluid.kinematicViscosity);
    reynoldsMin_ = std::min(reynoldsMin_, reynolds);
    reynoldsMax_ = std::max(reynoldsMax_, reynolds);
    responseTimeMin_ = std::min(responseTimeMin_, tau);
    responseTimeMax_ = std::max(responseTimeMax_, tau);
    radiusMin_ = std::min(radiusMin_, radius);
    radiusMax_ = std::max(radiusMax_, radius);
    referenceSpeed_ = std::max({referenceSpeed_, point.gasVelocity.norm(), point.velocity.norm()});

    // Forces of Eq. 3.3 and Sec. 3.4 per particle mass, and the deviations they drive.
    const Mat3& gradient = point.gasVelocityGradient;
    const Vec3 fluidAcceleration =
        slides::fluidAcceleration(point.gasVelocity, gradient, point.gasTimeDerivative);
    const Vec3 fluidVorticity = vorticity(gradient);
    track.spin =
        relaxSpin(track.spin, fluidVorticity,
                  spinResponseTime(rhoP, fluid.density, fluid.kinematicViscosity, radius), step.h);
    const auto lift = [&](LiftModel model) {
        return liftAcceleration(model, slip, fluidVorticity, track.spin, radius,
                                fluid.kinematicViscosity, fluid.density, rhoP);
    };
    const std::array<Vec3, forceTerms> accelerations{
        densityRatio_ * fluidAcceleration,
        sphereAddedMassCoefficient * densityRatio_ * (fluidAcceleration - point.acceleration),
        lift(LiftModel::saffmanMei), lift(LiftModel::magnus)};
    const double dragAcceleration = std::max(slipSpeed, 1e-9 * referenceSpeed_) / tau;
    for (int term = 0; term < forceTerms; ++term) {
        Vec3& deviation = track.deviation[static_cast<std::size_t>(term)];
        deviation =
            relaxDeviation(deviation, accelerations[static_cast<std::size_t>(term)], tau, step.h);
        largestDeviation_[term] = std::max(largestDeviation_[term], deviation.norm());
        peakToDrag_[term] =
            std::max(peakToDrag_[term], accelerations[term].norm() / dragAcceleration);
    }

    // Turbulence a particle takes on (Tchen) and the eddy time.
    if (point.turbulentEnergy > 0 && point.dissipationRate > 0) {
        const double lagrangian = lagrangianTimeScale(scene_.physics.dispersionConstants,
                                                      point.turbulentEnergy, point.dissipationRate);
        largestFluctuation_ =
            std::max(largestFluctuation_,
                     particleFluctuation(fluctuationRms(point.turbulentEnergy), lagrangian, tau));
        eddyTimes_.add(lagrangian);
    }

    // Heating (Sec. 3.8) with Ranz–Marshall, or its bound without c_p.
    const double nusselt = nusseltNumber(HeatTransferModel::ranzMarshall, reynolds, prandtl_);
    if (scene_.particles.specificHeat > 0) {
        const double thermalTime = thermalResponseTime(rhoP, scene_.particles.specificHeat, radius,
                                                       nusselt, fluid.thermalConductivity);
        track.temperature =
            relaxTemperature(track.temperature, point.gasTemperature, thermalTime, step.h);
        largestThermalRatio_ = std::max(largestThermalRatio_, tau / thermalTime);
    } else {
        track.temperature = point.gasTemperature;
    }
    largestTemperatureChange_ =
        std::max(largestTemperatureChange_,
                 std::abs(track.temperature - scene_.particles.injectionTemperature));
    if (scene_.particles.thermalConductivity > 0)
        largestBiot_ = std::max(largestBiot_, nusselt * fluid.thermalConductivity /
                                                  (6 * scene_.particles.thermalConductivity));

    // A tracer's step: the gas it sees changes by flowChangePerStep U_ref, it crosses half a
    // cell. The error that makes in the gas a particle sees reaches its velocity only over its
    // response time: after a flight t it has grown as (t/τ) h², so the step may grow by
    // √(τ/t) for a particle slower than its flight.
    const double speedSeen = point.velocity.norm();
    const double relaxation = std::sqrt(std::max(1.0, tau / step.time));
    const auto forResponse = [relaxation](double tracerStep) { return relaxation * tracerStep; };
    // The gas it sees changes at the rate ∂U/∂t + (∇U)v (∂U/∂t = 0 in a steady carrier).
    flowSteps_.add(forResponse(flowChangePerStep * referenceSpeed_ /
                               (gradient * point.velocity + point.gasTimeDerivative).norm()));
    crossingSteps_.add(forResponse(0.5 * point.resolutionLength / speedSeen));
    responseTimes_.add(tau);

    if (++track.sinceKept >= track.stride) {
        track.sinceKept = 0;
        track.times.push_back(step.time);
        track.slips.push_back(slip);
        track.responseTimes.push_back(tau);
        if (track.times.size() >= maxSlipSamples) { // keep the release and every other point
            std::size_t kept = 1;
            for (std::size_t j = 2; j < track.times.size(); j += 2, ++kept) {
                track.times[kept] = track.times[j];
                track.slips[kept] = track.slips[j];
                track.responseTimes[kept] = track.responseTimes[j];
            }
            track.times.resize(kept);
            track.slips.resize(kept);
            track.responseTimes.resize(kept);
            track.stride *= 2;
        }
    }
}

void PathEstimator::visitCloud(const PilotStep& step) {
    if (step.points.empty()) return;
    const JetNozzle& nozzle = scene_.nozzle;
    Vec3 meanVelocity = Vec3::Zero();
    double radiusCubed = 0, radialSquares = 0;
    for (const PathPoint& point : step.points) {
        meanVelocity += point.velocity;
        radiusCubed += std::pow(point.radius, 3);
        const Vec3 offset = point.position - nozzle.centre;
        radialSquares += (offset - offset.dot(nozzle.axis) * nozzle.axis).squaredNorm();
    }
    const double count = static_cast<double>(step.points.size());
    meanVelocity /= count;
    double velocitySpread = 0;
    for (const PathPoint& point : step.points)
        velocitySpread += (point.velocity - meanVelocity).squaredNorm();
    velocitySpread = std::sqrt(velocitySpread / count);
    const double meanRadius = std::cbrt(radiusCubed / count);
    const double particleVolume = 4.0 / 3.0 * std::numbers::pi * radiusCubed / count;
    // The spray's cross-section and speed against the nozzle's: the number density follows
    // from the flux of particles through the nozzle (or the sheet of particles injected at once).
    const double spread = std::max(std::sqrt(radialSquares / count), meanRadius);
    const double speed = std::max(meanVelocity.norm(), 1e-9 * referenceSpeed_);
    if (initialSpread_ == 0) {
        initialSpread_ = spread;
        initialSpeed_ = speed;
        // The densest injector's (each of `injectors {}` sprays through its own disc or patch).
        double nozzleDensity = 0;
        const auto injectors = injectorsOf(scene_);
        for (std::size_t k = 0; k < injectors.size(); ++k) {
            const InjectorSettings& injector = injectors[k];
            const double radius = std::max(injector.nozzle.radius, meanRadius);
            const double area = std::max(std::numbers::pi * std::pow(radius, 2), patchAreas_[k]);
            nozzleDensity = std::max(nozzleDensity, injector.injection.mode == InjectionMode::rate
                                                        ? injector.injection.rate / (area * speed)
                                                        : static_cast<double>(injector.count) /
                                                              (area * 2 * meanRadius));
        }
        volumeFractionNozzle_ = std::min(nozzleDensity * particleVolume, 0.64);
    }
    const double volumeFraction = std::min(
        volumeFractionNozzle_ * std::pow(initialSpread_ / spread, 2) * initialSpeed_ / speed, 0.64);
    volumeFractionMax_ = std::max(volumeFractionMax_, volumeFraction);
    // Relative speed of neighbours: the pilot's velocity spread and the turbulence they take on.
    const double relativeSpeed = std::sqrt(2.0) * std::hypot(velocitySpread, largestFluctuation_);
    const double rate = collisionRate(volumeFraction / particleVolume, meanRadius, relativeSpeed);
    largestCollisionRate_ = std::max(largestCollisionRate_, rate);
    // Along the flight of a typical particle: while half the pilot is in flight.
    if (2 * static_cast<long>(step.points.size()) >=
        std::min(scene_.particles.count, pilotParticles)) {
        expectedCollisions_ += rate * step.h;
        collisionVelocityChange_ += rate * step.h * relativeSpeed;
    }
}

void PathEstimator::endPath(ParticleId id, double time) {
    const auto found = tracks_.find(id);
    if (found == tracks_.end()) return;
    const Track& track = found->second;
    flightTimes_.push_back(time);
    // Basset's acceleration along the slip path, and the deviation it drives.
    Vec3 deviation = Vec3::Zero();
    for (std::size_t m = 1; m < track.times.size(); ++m) {
        const Vec3 history = bassetAcceleration(
            std::span(track.times).first(m + 1), std::span(track.slips).first(m + 1),
            track.times[m], track.radius, scene_.particles.density, scene_.fluid.density,
            scene_.fluid.kinematicViscosity);
        const double tau = track.responseTimes[m];
        deviation = relaxDeviation(deviation, history, tau, track.times[m] - track.times[m - 1]);
        largestHistoryDeviation_ = std::max(largestHistoryDeviation_, deviation.norm());
        const double dragAcceleration =
            std::max(track.slips[m].norm(), 1e-9 * referenceSpeed_) / tau;
        peakToDrag_[forceTerms] =
            std::max(peakToDrag_[forceTerms], history.norm() / dragAcceleration);
    }
    tracks_.erase(found);
}

/// value rounded down to two significant digits: a step a person can read.
double roundedDown(double value) {
    const double unit = std::pow(10.0, std::floor(std::log10(value)) - 1);
    return std::floor(value / unit + 1e-9) * unit;
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2g", value);
    return text;
}

void PathEstimator::decide(SceneAnalysis& analysis, const CarrierField& carrier) const {
    const double speed = std::max(referenceSpeed_, 1e-300);
    const CarrierNeeds provided = carrier.provides();
    for (const auto& row : physicsTermNames()) {
        TermDecision decision;
        decision.term = row.value;
        decision.peakToDrag = notANumber;
        decision.measure = "dv/U_ref";
        switch (row.value) {
        case PhysicsTerm::history:
            decision.effect = largestHistoryDeviation_ / speed;
            decision.peakToDrag = peakToDrag_[forceTerms];
            break;
        case PhysicsTerm::addedMass:
        case PhysicsTerm::pressureGradient:
        case PhysicsTerm::shearLift:
        case PhysicsTerm::spinLift:
            decision.effect = largestDeviation_[forceOf(row.value)] / speed;
            decision.peakToDrag = peakToDrag_[forceOf(row.value)];
            break;
        case PhysicsTerm::spin:
            decision.effect = largestDeviation_[spinLiftForce] / speed;
            decision.measure = "dv/U_ref of Magnus lift";
            break;
        case PhysicsTerm::dispersion:
            decision.effect = largestFluctuation_ / speed;
            decision.measure = "u'_p/U_ref";
            break;
        case PhysicsTerm::heatTransfer:
            decision.effect = largestTemperatureChange_ / scene_.fluid.temperature;
            decision.measure = scene_.particles.specificHeat > 0 ? "dT/T" : "dT/T (bound)";
            break;
        case PhysicsTerm::collisions:
            decision.effect = collisionVelocityChange_ / speed;
            decision.measure = "dv/U_ref of collisions";
            break;
        }
        const auto automatic =
            std::find_if(scene_.physics.automaticTerms.begin(), scene_.physics.automaticTerms.end(),
                         [&](const AutomaticTerm& term) { return term.term == row.value; });
        decision.automatic = automatic != scene_.physics.automaticTerms.end();
        const bool matters = decision.effect >= analysis.threshold;
        if (!decision.automatic) {
            decision.on = termIsOn(scene_, row.value);
            decision.reason = decision.on ? "set on" : "set off";
            if (!decision.on && matters && row.value != PhysicsTerm::spin)
                analysis.warnings.push_back(std::string(row.name) + " is set off, but its effect " +
                                            number(decision.effect) + " (" + decision.measure +
                                            ") reaches the threshold " +
                                            number(analysis.threshold));
        } else {
            std::string unavailable = automatic->unavailable;
            if (unavailable.empty() && row.value == PhysicsTerm::dispersion && !provided.turbulence)
                unavailable = "needs k and epsilon from the carrier";
            if (unavailable.empty() && row.value == PhysicsTerm::heatTransfer &&
                !provided.temperature)
                unavailable = "needs T from the carrier";
            decision.on = unavailable.empty() && matters;
            decision.reason = !unavailable.empty()
                                  ? "auto: " + unavailable
                                  : "auto: " + std::string(matters ? "reaches " : "below ") +
                                        number(analysis.threshold);
            if (!unavailable.empty() && matters)
                analysis.warnings.push_back(std::string(row.name) + " would matter (effect " +
                                            number(decision.effect) + ") but " + unavailable);
        }
        analysis.terms.push_back(decision);
    }
    // Spin left to auto follows Magnus lift.
    const auto decisionOf = [&](PhysicsTerm term) -> TermDecision& {
        return *std::find_if(analysis.terms.begin(), analysis.terms.end(),
                             [&](const TermDecision& d) { return d.term == term; });
    };
    TermDecision& spin = decisionOf(PhysicsTerm::spin);
    if (spin.automatic) {
        spin.on = decisionOf(PhysicsTerm::spinLift).on;
        spin.reason = spin.on ? "auto: Magnus lift is on" : "auto: Magnus lift is off";
    }
}

void PathEstimator::limitTimeStep(SceneAnalysis& analysis, const Scene& resolved) const {
    auto& limits = analysis.timeStepLimits;
    if (const double flow = flowSteps_.quantile(0.01); flow > 0) limits.push_back({"flow", flow});
    if (const double crossing = crossingSteps_.quantile(0.01); crossing > 0)
        limits.push_back({"cellCrossing", crossing});
    if (resolved.time.integrator == Integrator::explicitEuler || resolved.physics.unsteadyForces())
        limits.push_back({"responseTime", 0.2 * responseTimes_.quantile(0.01)});
    if (resolved.physics.dispersion != DispersionModel::none && eddyTimes_.quantile(0.01) > 0)
        limits.push_back({"eddyLifetime", eddyTimes_.quantile(0.01)});
    if (resolved.collisions.model != CollisionModel::none && largestCollisionRate_ > 0)
        limits.push_back({"collisionTime", 0.25 / largestCollisionRate_});
    if (resolved.collisions.model == CollisionModel::softSphere && radiusMax_ > 0) {
        // Eq. 2.59: the shortest Hertz contact, of the smallest spheres at the largest speed
        // (or that of the other contact laws, physics/contact_laws.h).
        // With differing species, the shortest over every pair of them.
        double duration = INFINITY;
        const std::vector<ParticleSpecies> species = resolved.particles.allSpecies();
        for (const ParticleSpecies& a : species)
            for (const ParticleSpecies& b : species) {
                const ContactPair pair =
                    contactPair({sphereMass(radiusMin_, a.density), radiusMin_, &a.material},
                                {sphereMass(radiusMin_, b.density), radiusMin_, &b.material});
                duration = std::min(
                    duration, resolved.collisions.softSphere.contactLaw == NormalContactLaw::hertz
                                  ? hertzContactDuration(pair, referenceSpeed_)
                                  : softContactDuration(pair, softContactLawOf(resolved.collisions),
                                                        referenceSpeed_));
            }
        limits.push_back({"contactDuration", duration / stepsPerSoftContact});
    }
    const ElectromagneticSettings& charged = resolved.physics.electromagnetic;
    if (charged.on() && charged.coulomb.on() && radiusMax_ > 0) {
        // A fixed charge pushes the smallest particles hardest; a surface charge the largest.
        double shortest = INFINITY;
        for (const double radius : {radiusMin_, radiusMax_})
            shortest =
                std::min(shortest, coulombTime(charged.coulomb, charged.chargeOfModel(radius),
                                               sphereMass(radius, resolved.particles.density),
                                               std::min(2 * radius, charged.coulomb.cutoff)));
        if (std::isfinite(shortest))
            limits.push_back({"coulombTime", shortest / stepsPerCoulombTime});
    }
    if (charged.on() && !charged.uniform()) {
        // The fastest a particle crosses the coils' fields: the reference speed, or the speed a
        // magnetisable particle gains falling into the strongest field, √(|χm|/(µ0 µr ρp)) B
        // (its energy χm B²/(2 µ0 µr) a unit volume, Eq. 2.110), B at the coils' centres.
        double smallestCoil = INFINITY, strongest = charged.magneticField.norm();
        for (const CurrentLoop& coil : charged.coils) {
            smallestCoil = std::min(smallestCoil, coil.radius);
            strongest += vacuumPermeability * std::abs(coil.current) / (2 * coil.radius);
        }
        double falling = 0; // the fastest species
        if (charged.magnetisable())
            for (const ParticleSpecies& species : resolved.particles.allSpecies())
                falling =
                    std::max(falling, std::sqrt(std::abs(species.susceptibility) /
                                                (vacuumPermeability * (1 + species.susceptibility) *
                                                 species.density)) *
                                          strongest);
        const double speed = std::max(referenceSpeed_, falling);
        if (speed > 0) limits.push_back({"coilField", smallestCoil / (stepsPerCoilRadius * speed)});
    }
    limits.push_back({"outputInterval", resolved.output.interval});
    limits.push_back({"endTime", resolved.time.endTime});
    const auto smallest =
        std::min_element(limits.begin(), limits.end(),
                         [](const auto& a, const auto& b) { return a.value < b.value; });
    analysis.suggestedTimeStep = roundedDown(smallest->value);
    analysis.timeStepLimitedBy = smallest->name;
}

void PathEstimator::fillFigures(SceneFigures& figures) const {
    const Scene& scene = scene_;
    figures.referenceSpeed = referenceSpeed_;
    figures.densityRatio = scene.particles.density / scene.fluid.density;
    const double flowTime = scene.nozzle.radius / std::max(referenceSpeed_, 1e-300);
    const auto stokes = [&](double radius) {
        return stokesResponseTime(scene.particles.density, radius, scene.fluid.density,
                                  scene.fluid.kinematicViscosity) /
               flowTime;
    };
    figures.stokesNumberMin = radiusMax_ > 0 ? stokes(radiusMin_) : notANumber;
    figures.stokesNumberMax = radiusMax_ > 0 ? stokes(radiusMax_) : notANumber;
    figures.reynoldsMin = reynoldsMax_ > 0 ? reynoldsMin_ : 0;
    figures.reynoldsMax = reynoldsMax_;
    figures.responseTimeMin = responseTimeMax_ > 0 ? responseTimeMin_ : notANumber;
    figures.responseTimeMax = responseTimeMax_ > 0 ? responseTimeMax_ : notANumber;
    std::vector<double> flights = flightTimes_;
    std::sort(flights.begin(), flights.end());
    figures.flightTime = flights.empty() ? 0 : flights[flights.size() / 2];
    figures.volumeFractionNozzle = volumeFractionNozzle_;
    figures.volumeFractionMax = volumeFractionMax_;
    figures.collisionsPerParticle = expectedCollisions_;
    figures.biotMax = scene.particles.thermalConductivity > 0 ? largestBiot_ : notANumber;
}

/// A first step for the pilot: a fiftieth of the nozzle radius at the nozzle's gas speed.
double provisionalTimeStep(const Scene& scene, const CarrierField& carrier) {
    const JetNozzle& nozzle = scene.nozzle;
    const Vec3 exit = nozzle.centre + 0.01 * nozzle.radius * nozzle.axis;
    CarrierSample gas;
    carrier.sample(std::span(&exit, 1), 0, CarrierNeeds{}, gas);
    const double speed = gas.velocity[0].norm() > 0 ? gas.velocity[0].norm() : 1.0;
    const Vec3 diagonal = scene.domain.max - scene.domain.min;
    const double length = std::max(nozzle.radius, 1e-3 * diagonal.norm());
    return std::min({0.02 * length / speed, scene.output.interval, scene.time.endTime / 100});
}

/// Switches every term left to auto as the analysis decided.
void setAutomaticTerms(const std::vector<TermDecision>& decisions, Scene& scene) {
    for (const TermDecision& decision : decisions)
        if (decision.automatic) setTerm(scene, decision.term, decision.on);
}

} // namespace

/// A scene without gas (carrier none) has nothing to trace: every term keeps its setting, those
/// left to auto stay off, and the time step is the one given.
SceneAnalysis analyseWithoutGas(const Scene& scene) {
    SceneAnalysis analysis;
    analysis.threshold = scene.physics.autoThreshold;
    analysis.timeStepGiven = true;
    for (const auto& row : physicsTermNames()) {
        TermDecision decision;
        decision.term = row.value;
        decision.effect = notANumber;
        decision.peakToDrag = notANumber;
        decision.measure = "-";
        decision.automatic =
            std::any_of(scene.physics.automaticTerms.begin(), scene.physics.automaticTerms.end(),
                        [&](const AutomaticTerm& term) { return term.term == row.value; });
        decision.on = !decision.automatic && termIsOn(scene, row.value);
        decision.reason = decision.automatic ? "auto: no carrier gas to estimate it"
                          : decision.on      ? "set on"
                                             : "set off";
        analysis.terms.push_back(decision);
    }
    analysis.suggestedTimeStep = scene.time.dt;
    analysis.timeStepLimitedBy = "time.dt";
    return analysis;
}

SceneAnalysis analyseScene(const Scene& given, const CarrierField& carrier) {
    if (given.carrier.type == CarrierType::none) return analyseWithoutGas(given);
    // Differing species: the pilot particles fly as their own, and the estimates are those of
    // the lightest species, whose response time at each radius is the shortest (τ ∝ ρp) and
    // whose unsteady terms, relative to the drag, the largest (added mass, pressure gradient,
    // lift and history grow with ρf/ρp, Eq. 3.3); heating as the species whose thermal response
    // time is the shortest (τ_θ ∝ ρp c_p).
    Scene lightest;
    if (!given.particles.alike()) {
        lightest = given;
        const auto& species = given.particles.species;
        const ParticleSpecies& light =
            *std::min_element(species.begin(), species.end(),
                              [](const auto& a, const auto& b) { return a.density < b.density; });
        const ParticleSpecies& quickest =
            *std::min_element(species.begin(), species.end(), [](const auto& a, const auto& b) {
                return a.density * a.specificHeat < b.density * b.specificHeat;
            });
        lightest.particles.density = light.density;
        lightest.particles.material = light.material;
        lightest.particles.specificHeat = quickest.density * quickest.specificHeat / light.density;
    }
    const Scene& scene = given.particles.alike() ? given : lightest;
    SceneAnalysis analysis;
    analysis.threshold = scene.physics.autoThreshold;
    analysis.timeStepGiven = scene.time.dt > 0;
    const double pilotStep =
        analysis.timeStepGiven ? scene.time.dt : provisionalTimeStep(scene, carrier);
    PathEstimator estimator(scene, carrier);
    analysis.pilot =
        tracePilotPaths(scene, carrier, pilotStep, [&](const PilotStep& step) { estimator(step); });
    estimator.finish(analysis.pilot.steps * pilotStep);
    estimator.fillFigures(analysis.figures);
    estimator.decide(analysis, carrier);
    if (analysis.pilot.unfinished > 0)
        analysis.warnings.push_back(std::to_string(analysis.pilot.unfinished) + " of " +
                                    std::to_string(analysis.pilot.particles) +
                                    " pilot particles were still in flight when the pilot ended");
    if (analysis.figures.biotMax > 0.1)
        analysis.warnings.push_back("Biot number " + number(analysis.figures.biotMax) +
                                    " > 0.1: the lumped particle temperature of Sec. 3.8 does "
                                    "not hold");
    Scene resolved = scene;
    setAutomaticTerms(analysis.terms, resolved);
    estimator.limitTimeStep(analysis, resolved);
    if (analysis.timeStepGiven && scene.time.dt > 2 * analysis.suggestedTimeStep)
        analysis.warnings.push_back("time.dt " + number(scene.time.dt) + " s is above the " +
                                    number(analysis.suggestedTimeStep) +
                                    " s the analysis "
                                    "suggests (" +
                                    analysis.timeStepLimitedBy + ")");
    return analysis;
}

void applyAnalysis(const SceneAnalysis& analysis, Scene& scene) {
    setAutomaticTerms(analysis.terms, scene);
    if (!analysis.timeStepGiven) scene.time.dt = analysis.suggestedTimeStep;
}

std::string describeAnalysis(const SceneAnalysis& analysis) {
    const SceneFigures& f = analysis.figures;
    std::ostringstream text;
    char line[256];
    std::snprintf(line, sizeof line,
                  "  analysis   pilot %ld particles, %ld steps of %.3g s; U_ref %.3g m/s, "
                  "rho_p/rho_f %.4g, Stokes number %.3g-%.3g, Re %.3g-%.3g, flight %.3g s\n",
                  analysis.pilot.particles, analysis.pilot.steps, analysis.pilot.dt,
                  f.referenceSpeed, f.densityRatio, f.stokesNumberMin, f.stokesNumberMax,
                  f.reynoldsMin, f.reynoldsMax, f.flightTime);
    text << line;
    std::snprintf(line, sizeof line,
                  "             volume fraction %.3g at the nozzle (max %.3g), %.3g collisions "
                  "per particle, Biot %.3g\n",
                  f.volumeFractionNozzle, f.volumeFractionMax, f.collisionsPerParticle, f.biotMax);
    text << line;
    std::snprintf(line, sizeof line, "             %-17s %-9s %-10s %-24s %s (threshold %.3g)\n",
                  "term", "effect", "force/drag", "measure", "decision", analysis.threshold);
    text << line;
    for (const TermDecision& d : analysis.terms) {
        std::snprintf(line, sizeof line, "             %-17s %-9.2e %-10.2e %-24s %-3s %s\n",
                      std::string(physicsTermRow(d.term).name).c_str(), d.effect, d.peakToDrag,
                      d.measure.c_str(), d.on ? "on" : "off", d.reason.c_str());
        text << line;
    }
    text << "             time step " << number(analysis.suggestedTimeStep) << " s suggested ("
         << analysis.timeStepLimitedBy << ";";
    for (const TimeStepLimit& limit : analysis.timeStepLimits)
        text << " " << limit.name << " " << number(limit.value);
    text << ")" << (analysis.timeStepGiven ? ", time.dt given" : ", used") << "\n";
    for (const std::string& warning : analysis.warnings) text << "  warning    " << warning << "\n";
    return text.str();
}

} // namespace slides
