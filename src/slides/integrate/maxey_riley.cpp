#include "slides/integrate/maxey_riley.h"

#include "slides/core/parallel.h"
#include "slides/physics/drag_response.h"
#include "slides/physics/faxen.h"
#include "slides/physics/history_kernel.h"
#include "slides/physics/lift.h"
#include "slides/physics/particle_reynolds.h"
#include "slides/physics/spin.h"

#include <cmath>
#include <span>

namespace slides {

MaxeyRileyStepper::MaxeyRileyStepper(const PhysicsSettings& physics, const FluidSettings& fluid,
                                     std::span<const double> densities, const TimeSettings& time,
                                     bool steadyCarrier)
    : physics_(physics), fluid_(fluid), inertia_{physics.addedMass, physics.pressureGradient} {
    for (const double density : densities)
        species_.push_back(
            {density,
             {physics.drag, fluid.density, fluid.kinematicViscosity, density},
             inertia_.effectiveDensity(density, fluid.density),
             inertia_.bodyAcceleration(physics.gravity, density, fluid.density, physics.buoyancy),
             inertia_.fluidAccelerationFactor(density, fluid.density)});
    needs_.velocityGradient = physics.addedMass || physics.pressureGradient ||
                              physics.lift != LiftModel::none || physics.spin;
    needs_.timeDerivative = !steadyCarrier && (physics.addedMass || physics.pressureGradient);
    needs_.velocityLaplacian = physics.faxen;
    width_ = 4; // age, v_{n−1}
    history_ = physics.history != HistoryModel::none;
    spinHistory_ = physics.spin && physics.spinHistory;
    if (!history_ && !spinHistory_) return;
    const bool finiteReynolds =
        physics.history == HistoryModel::meiAdrian || physics.history == HistoryModel::kim;
    memory_ = WindowTailLayout::make(time.dt, time.endTime, physics.historyAccuracy,
                                     finiteReynolds ? LowRates::truncated : LowRates::lumped);
    if (finiteReynolds) {
        finiteReynolds_ = FiniteReynoldsLayout::make(*memory_, time.endTime);
        finiteReynoldsTables_ = &FiniteReynoldsKernel::of(
            physics.history == HistoryModel::kim ? kimShape : meiAdrianShape);
    }
    if (history_) { // s0, I_n (A_n for the finite-Reynolds kernels), memory
        historyOffset_ = width_;
        width_ += 6 + (finiteReynolds_ ? finiteReynolds_->doubles() : memory_->doubles());
    }
    if (spinHistory_) {
        spinHistoryOffset_ = width_;
        width_ += 6 + memory_->doubles(); // σ0, I_n, memory
    }
}

Vec3 MaxeyRileyStepper::spinWithHistory(double* state, double age, const Vec3& spin,
                                        const Vec3& rotationStart, const Vec3& rotationEnd,
                                        double radius, double density, double h) const {
    const double viscosity = fluid_.kinematicViscosity;
    const double responseTime = spinResponseTime(density, fluid_.density, viscosity, radius);
    const HistoryKernel kernel{radius * radius / viscosity};
    SlipStep step;
    step.h = h;
    step.dragRate = 1.0 / responseTime;
    step.historyRate = spinHistoryRate(responseTime, kernel.viscousTime);
    step.gasStart = rotationStart;
    step.gasEnd = rotationEnd;
    Eigen::Map<Vec3> startSlip(state), integral(state + 3);
    if (age == 0) startSlip = rotationStart - spin; // released now, into fluid at rest
    HistoryStart start{startSlip, age, integral};
    WindowTailHistory memory(*memory_, state + 6, kernel);
    const Vec3 next = advanceWithHistory(step, spin, start, memory).velocity;
    integral = start.integral;
    return next;
}

Vec3 MaxeyRileyStepper::dragGasVelocity(const CarrierSample& gas, std::size_t i,
                                        double radius) const {
    return needs_.velocityLaplacian
               ? faxenDragVelocity(gas.velocity[i], gas.velocityLaplacian[i], radius)
               : gas.velocity[i];
}

void MaxeyRileyStepper::advance(ParticleCloud& cloud, const CarrierSample& gasStart,
                                const EndSampler& sampleEnd, const std::vector<double>& stepLengths,
                                std::span<const std::int32_t> species,
                                std::span<const double> densities) {
    const auto count = static_cast<std::ptrdiff_t>(cloud.size());
    const auto termsOf = [&](std::ptrdiff_t i) -> const SpeciesTerms& {
        return species_[species.empty() ? 0 : static_cast<std::size_t>(species[i])];
    };
    auto& x = cloud.position;
    auto& v = cloud.velocity;
    const auto stateOf = [&](std::ptrdiff_t i) {
        return cloud.modelState.data() + static_cast<std::size_t>(i) * cloud.stateWidth;
    };
    const double fluidDensity = fluid_.density;
    const double viscosity = fluid_.kinematicViscosity;
    const double addedMass = inertia_.addedMassCoefficient();
    // Prediction of the step's end on the smooth part w = v + s0 φ(age) of the velocity (the
    // start mode s0 φ carries the √t of a release with slip): w_{n+1} ≈ 2 w_n − w_{n−1} (w_n on
    // the first step), v* = w_{n+1} − s0 φ_{n+1}, x* = x + h (w_n + w_{n+1})/2 − s0 ∫φ.
    predicted_.resize(cloud.size());
    predictedVelocity_.resize(cloud.size());
    smoothVelocity_.resize(cloud.size());
    startModes_.resize(cloud.size());
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
    for (std::ptrdiff_t i = 0; i < count; ++i) {
        double* state = stateOf(i);
        const double h = stepLengths[i];
        StartModeStep& modes = startModes_[i];
        modes = {};
        Vec3 startSlip = Vec3::Zero();
        if (history_) {
            Eigen::Map<Vec3> s0(state + historyOffset_);
            if (state[0] == 0) s0 = dragGasVelocity(gasStart, i, cloud.radius[i]) - v[i]; // now
            startSlip = s0;
            const double historyRate = bassetHistoryRate(termsOf(i).density, fluidDensity,
                                                         viscosity, cloud.radius[i], addedMass);
            modes = startModeStep(historyRate, HistoryStart{startSlip, state[0]}, h);
        }
        const StartMode& now = modes.before;
        const StartMode& next = modes.after;
        const Vec3 smooth = v[i] + now.value * startSlip;
        const Vec3 previous = state[0] > 0 ? Vec3(state + 1) : smooth;
        const Vec3 smoothNext = 2 * smooth - previous;
        smoothVelocity_[i] = smooth;
        predictedVelocity_[i] = smoothNext - next.value * startSlip;
        predicted_[i] =
            x[i] + 0.5 * h * (smooth + smoothNext) - (next.integral - now.integral) * startSlip;
    }
    sampleEnd(predicted_, gasEnd_);

    // The drag response times the step freezes k at (below), in SIMD lanes: at the slips of both
    // ends after a release with slip, else at the predicted midpoint slip (the end's unused).
    const auto releasedWithSlip = [&](const double* state) {
        return history_ && !Vec3(state + historyOffset_).isZero(0);
    };
    slipSpeeds_.resize(2 * cloud.size());
    responseTimes_.resize(2 * cloud.size());
    const auto starts = std::span(slipSpeeds_).first(cloud.size());
    const auto ends = std::span(slipSpeeds_).last(cloud.size());
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
    for (std::ptrdiff_t i = 0; i < count; ++i) {
        const auto n = static_cast<std::size_t>(i);
        const Vec3 slipStart = dragGasVelocity(gasStart, n, cloud.radius[n]) - v[n];
        const Vec3 slipEnd = dragGasVelocity(gasEnd_, n, cloud.radius[n]) - predictedVelocity_[n];
        const bool bothEnds = releasedWithSlip(stateOf(i));
        starts[n] = (bothEnds ? slipStart : Vec3(0.5 * (slipStart + slipEnd))).norm();
        ends[n] = bothEnds ? slipEnd.norm() : 0.0;
    }
    const auto tauStart = std::span(responseTimes_).first(cloud.size());
    const auto tauEnd = std::span(responseTimes_).last(cloud.size());
    const DragParameters& drag = species_.front().drag; // ρp: densities, when given
    dragResponseTimes(drag, cloud.radius, starts, tauStart, densities);
    dragResponseTimes(drag, cloud.radius, ends, tauEnd, densities);

    const LiftModel lift = physics_.lift;
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
    for (std::ptrdiff_t i = 0; i < count; ++i) {
        double* state = stateOf(i);
        const SpeciesTerms& terms = termsOf(i);
        const double particleDensity = terms.density, effectiveDensity = terms.effectiveDensity;
        const double radius = cloud.radius[i];
        const Vec3 velocity = v[i];
        const Vec3& u0 = gasStart.velocity[i];
        const Vec3& u1 = gasEnd_.velocity[i];
        const Vec3 slipStart = u0 - velocity, slipEnd = u1 - predictedVelocity_[i];

        SlipStep step;
        step.h = stepLengths[i];
        step.gasStart = dragGasVelocity(gasStart, static_cast<std::size_t>(i), radius);
        step.gasEnd = dragGasVelocity(gasEnd_, static_cast<std::size_t>(i), radius);
        // Drag per effective mass k = f(Re)/τ_e = (ρp/ρ_e)/τ, frozen at its mean over the step:
        // at the predicted midpoint slip; after a release with slip, k varies as √age like the
        // slip, so the mean of k_n + (k_{n+1} − k_n)(√t − √t_n)/(√t_{n+1} − √t_n) over the step,
        // k_n + (k_{n+1} − k_n)(2b + a)/(3(a + b)), a = √t_n, b = √t_{n+1} (2/3 on the first step,
        // → ½ later): the midpoint would cost half an order there.
        const auto n = static_cast<std::size_t>(i);
        const double kStart = particleDensity / effectiveDensity / tauStart[n];
        if (releasedWithSlip(state)) {
            const double a = std::sqrt(state[0]), b = std::sqrt(state[0] + step.h);
            const double kEnd = particleDensity / effectiveDensity / tauEnd[n];
            step.dragRate = kStart + (kEnd - kStart) * (2 * b + a) / (3 * (a + b));
        } else {
            step.dragRate = kStart;
        }
        step.forceStart = step.forceEnd = terms.bodyAcceleration;
        if (needs_.velocityLaplacian && physics_.addedMass && step.h > 0) {
            // C_A m_f d/dt((R²/10)∇²u) per effective mass, constant over the step so that the
            // trapezoid rule integrates it to the difference of its ends (physics/faxen.h).
            const Vec3 change = faxenAddedMassCorrection(gasEnd_.velocityLaplacian[i], radius) -
                                faxenAddedMassCorrection(gasStart.velocityLaplacian[i], radius);
            const Vec3 acceleration = addedMass * fluidDensity / effectiveDensity * change / step.h;
            step.forceStart += acceleration;
            step.forceEnd += acceleration;
        }
        if (needs_.velocityGradient) {
            const Mat3& grad0 = gasStart.velocityGradient[i];
            const Mat3& grad1 = gasEnd_.velocityGradient[i];
            const double fluidAcceleration = terms.fluidAccelerationFactor;
            step.forceStart += fluidAcceleration * steadyFluidAcceleration(u0, grad0);
            step.forceEnd += fluidAcceleration * steadyFluidAcceleration(u1, grad1);
            if (needs_.timeDerivative) {
                step.forceStart += fluidAcceleration * gasStart.velocityTimeDerivative[i];
                step.forceEnd += fluidAcceleration * gasEnd_.velocityTimeDerivative[i];
            }
            const Vec3 vorticity0 = vorticity(grad0), vorticity1 = vorticity(grad1);
            Vec3 spinStart = Vec3::Zero(), spinEnd = Vec3::Zero();
            if (physics_.spin) {
                Vec3& spin = cloud.angularVelocity[static_cast<std::size_t>(i)];
                spinStart = spin;
                spin = spinHistory_ ? spinWithHistory(state + spinHistoryOffset_, state[0], spin,
                                                      0.5 * vorticity0, 0.5 * vorticity1, radius,
                                                      particleDensity, step.h)
                                    : relaxSpin(spin, 0.5 * (vorticity0 + vorticity1),
                                                spinResponseTime(particleDensity, fluidDensity,
                                                                 viscosity, radius),
                                                step.h);
                spinEnd = spin;
            }
            if (lift != LiftModel::none) {
                step.forceStart += liftAcceleration(lift, slipStart, vorticity0, spinStart, radius,
                                                    viscosity, fluidDensity, effectiveDensity);
                step.forceEnd += liftAcceleration(lift, slipEnd, vorticity1, spinEnd, radius,
                                                  viscosity, fluidDensity, effectiveDensity);
            }
        }

        StepResult result;
        if (history_) {
            step.historyRate =
                bassetHistoryRate(particleDensity, fluidDensity, viscosity, radius, addedMass);
            double* historyState = state + historyOffset_;
            Eigen::Map<Vec3> startSlip(historyState), integral(historyState + 3);
            HistoryStart start{startSlip, state[0], integral};
            if (finiteReynolds_) {
                FiniteReynoldsWindowTail memory(
                    *finiteReynolds_, historyState + 6,
                    SlipKernel{finiteReynoldsTables_, radius, viscosity});
                if (state[0] == 0) { // released now: the jump, Kim's with G1 (Eq. 3.13–3.14)
                    const double slip = startSlip.norm();
                    const double g1 =
                        physics_.history == HistoryModel::kim
                            ? kimInitialFactor(particleReynolds(slip, radius, viscosity),
                                               particleDensity / fluidDensity)
                            : 1.0;
                    memory.start(startSlip, crossoverLag(finiteReynoldsTables_->shape(), slip,
                                                         radius, viscosity, g1));
                }
                result = advanceWithHistory(step, velocity, start, memory, startModes_[i]);
            } else {
                WindowTailHistory memory(*memory_, historyState + 6);
                result = advanceWithHistory(step, velocity, start, memory, startModes_[i]);
            }
            integral = start.integral;
        } else {
            NoHistory memory;
            HistoryStart start;
            result = advanceWithHistory(step, velocity, start, memory);
        }
        Eigen::Map<Vec3>(state + 1) = smoothVelocity_[i];
        state[0] += step.h;
        x[i] += result.displacement;
        v[i] = result.velocity;
    }
}

} // namespace slides
