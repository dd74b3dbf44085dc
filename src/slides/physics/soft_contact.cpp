#include "slides/physics/soft_contact.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace slides {

namespace {

/// Tsuji's damping factor −2√(5/6) β shared by the normal and the tangential damping.
double dampingFactor(const SoftContactLaw& law) {
    return -2.0 * std::sqrt(5.0 / 6.0) * law.dampingRatio;
}

/// Hertz contact radius √(R*δ) [m]: the stiffnesses are proportional to it.
double contactRadius(const ContactPair& pair, double overlap) {
    return std::sqrt(pair.radius * overlap);
}

} // namespace

double liggghtsDampingRatio(double restitution) {
    const double logE = std::log(restitution);
    return logE / std::sqrt(logE * logE + std::numbers::pi * std::numbers::pi);
}

double restitutionOfDampingRatio(double dampingRatio) {
    // δ in units of δ0, t of t0 with m* δ0/t0² = 4/3 E*√R* δ0^{3/2} and δ0/t0 = v: the damping
    // −2√(5/6) β √(S_n m*) dδ/dt becomes κ x^{1/4} x' with κ = −2√(5/6)·√(3/2) β = −√5 β.
    const double kappa = -std::sqrt(5.0) * dampingRatio;
    const auto acceleration = [kappa](double x, double v) {
        return x <= 0 ? 0.0 : -std::max(0.0, std::pow(x, 1.5) + kappa * std::pow(x, 0.25) * v);
    };
    const double h = 5e-4; // the elastic impact lasts 3.2: RK4 error < 1e-5 in e
    double x = 0, v = 1;
    for (long step = 0; step < 100'000'000; ++step) {
        const double a1 = acceleration(x, v);
        const double a2 = acceleration(x + 0.5 * h * v, v + 0.5 * h * a1);
        const double a3 = acceleration(x + 0.5 * h * (v + 0.5 * h * a1), v + 0.5 * h * a2);
        const double a4 = acceleration(x + h * (v + 0.5 * h * a2), v + h * a3);
        x += h / 6 * (v + 2 * (v + 0.5 * h * a1) + 2 * (v + 0.5 * h * a2) + (v + h * a3));
        v += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
        // Once the clamped force is zero the bodies fly apart at constant speed.
        if (x <= 0) return -v;
    }
    return 0.0; // overdamped: it never leaves (not reached for β > −10)
}

SoftContactLaw softContactLaw(double restitution, double friction) {
    // The scene reader checks the range; reaching here outside it is a broken invariant.
    if (!(restitution > 0.0 && restitution <= 1.0))
        throw std::logic_error("softContactLaw: restitution " + std::to_string(restitution) +
                               " outside (0, 1]");
    if (restitution == 1.0) return {0.0, friction};
    // e(β) falls monotonically as β goes negative: bracket, then bisect.
    double elastic = 0.0, damped = 2.0 * liggghtsDampingRatio(restitution);
    while (restitutionOfDampingRatio(damped) > restitution) damped *= 2.0;
    for (int iteration = 0; iteration < 60 && elastic - damped > 1e-12; ++iteration) {
        const double middle = 0.5 * (elastic + damped);
        (restitutionOfDampingRatio(middle) > restitution ? elastic : damped) = middle;
    }
    return {0.5 * (elastic + damped), friction};
}

double dampingCoefficient(const ContactPair& pair, const SoftContactLaw& law, double overlap) {
    switch (law.normalLaw) {
    case NormalContactLaw::hertz: // γ_n = −2√(5/6) β √(S_n m*), S_n = 2E*√(R*δ)
        return dampingFactor(law) *
               std::sqrt(2.0 * pair.youngsModulus * contactRadius(pair, overlap) * pair.mass);
    case NormalContactLaw::linearSpringDashpot: // γ = 2ζ√(k m*) (Eq. 2.6, 2.7)
        return 2 * linearDampingRatio(law.restitution) * std::sqrt(law.normalStiffness * pair.mass);
    case NormalContactLaw::viscoelasticHertz: // 3/2 K_n A √δ (Eq. 2.8)
        return 2.0 * pair.youngsModulus * law.dissipativeTime * contactRadius(pair, overlap);
    case NormalContactLaw::waltonBraun: return 0; // hysteresis, no dashpot
    }
    return 0;
}

namespace {

/// The exponent p of the law's damping coefficient γ ∝ δ^p: 1/4 (hertz: γ_n ∝ √S_n ∝ δ^{1/4}),
/// 1/2 (viscoelasticHertz), 0 (linearSpringDashpot; waltonBraun has none).
double dampingExponent(const SoftContactLaw& law) {
    switch (law.normalLaw) {
    case NormalContactLaw::hertz: return 0.25;
    case NormalContactLaw::viscoelasticHertz: return 0.5;
    case NormalContactLaw::linearSpringDashpot:
    case NormalContactLaw::waltonBraun: return 0;
    }
    return 0;
}

} // namespace

double dampingPotential(const ContactPair& pair, const SoftContactLaw& law, double overlap) {
    if (!(overlap > 0)) return 0;
    // γ ∝ δ^p integrates to γ(δ) δ/(1 + p).
    return dampingCoefficient(pair, law, overlap) * overlap / (1 + dampingExponent(law));
}

double hertzNormalForce(const ContactPair& pair, const SoftContactLaw& law, double overlap,
                        double closingSpeed) {
    return std::max(0.0, elasticNormalForce(pair, law, overlap) +
                             dampingCoefficient(pair, law, overlap) * closingSpeed);
}

double normalContactForce(const ContactPair& pair, const SoftContactLaw& law, double overlap,
                          double closingSpeed, double dt, double& largestOverlap) {
    largestOverlap = std::max(largestOverlap, overlap);
    if (law.normalLaw == NormalContactLaw::waltonBraun)
        return waltonBraunForce(law.normalStiffness, law.restitution, overlap, largestOverlap);
    const double elastic = elasticNormalForce(pair, law, overlap);
    const double damping = dampingCoefficient(pair, law, overlap);
    double force = elastic + damping * closingSpeed;
    if (dt > 0) {
        // The step's kicks apply this force over [t − dt/2, t + dt/2], where the damping's
        // impulse is Φ(δ(t + dt/2)) − Φ(δ(t − dt/2)): δ(t − dt/2) half a drift d back, or the
        // touch (Φ = 0) if the contact began within this drift; δ(t + dt/2) half a drift ahead
        // at the velocity that the force leaves, u − F dt/m*: to first order in F, a factor
        // 1/(1 + γ dt/2m*) on the force.
        const double drift = closingSpeed * dt;
        double impulse;
        if (std::abs(drift) < overlap) {
            // Well inside the contact, |d| < δ: Φ(δ + d/2) − Φ(δ − d/2) = γ(δ) d (1 + p(p − 1)/24
            // (d/δ)² + …), the next term below 5e-4 of it. No root beyond γ's own.
            const double ratio = drift / overlap, exponent = dampingExponent(law);
            impulse = damping * drift * (1 + exponent * (exponent - 1) / 24 * ratio * ratio);
        } else {
            const double start =
                overlap - drift > 0 ? dampingPotential(pair, law, overlap - 0.5 * drift) : 0.0;
            impulse = dampingPotential(pair, law, overlap + 0.5 * drift) - start;
        }
        force = (elastic + impulse / dt) / (1 + 0.5 * dt * damping / pair.mass);
    }
    return mayPull(law) ? force : std::max(0.0, force);
}

double partingNormalForce(const ContactPair& pair, const SoftContactLaw& law, double overlap,
                          double closingSpeed, double dt) {
    if (!mayPull(law) || !(dt > 0)) return 0;
    // The last step's kicks applied the dashpot up to δ(t − dt/2), half a drift back from this
    // step's δ ≤ 0; from there to the parting (δ = 0) its impulse is Φ(0) − Φ(δ(t − dt/2)).
    return -dampingPotential(pair, law, overlap - 0.5 * closingSpeed * dt) / dt;
}

double elasticNormalForce(const ContactPair& pair, const SoftContactLaw& law, double overlap) {
    switch (law.normalLaw) {
    case NormalContactLaw::hertz:
    case NormalContactLaw::viscoelasticHertz: // k_n δ, k_n = 4/3 E* √(R*δ) (Eq. 2.4)
        return 4.0 / 3.0 * pair.youngsModulus * contactRadius(pair, overlap) * overlap;
    case NormalContactLaw::linearSpringDashpot:
    case NormalContactLaw::waltonBraun: return law.normalStiffness * overlap;
    }
    return 0;
}

double softContactDuration(const ContactPair& pair, const SoftContactLaw& law, double impactSpeed) {
    switch (law.normalLaw) {
    case NormalContactLaw::hertz:
    case NormalContactLaw::viscoelasticHertz: return hertzContactDuration(pair, impactSpeed);
    case NormalContactLaw::linearSpringDashpot:
        return linearContactDuration(law.normalStiffness, pair.mass,
                                     linearDampingRatio(law.restitution));
    case NormalContactLaw::waltonBraun:
        return waltonBraunContactDuration(law.normalStiffness, pair.mass, law.restitution);
    }
    return 0;
}

double mindlinStiffness(const ContactPair& pair, double overlap) {
    return 8.0 * pair.shearModulus * contactRadius(pair, overlap);
}

double hertzElasticEnergy(const ContactPair& pair, double overlap) {
    return 8.0 / 15.0 * pair.youngsModulus * std::sqrt(pair.radius) * std::pow(overlap, 2.5);
}

Vec3 mindlinTangentialForce(TangentialSpring& spring, const ContactPair& pair,
                            const SoftContactLaw& law, double overlap, const Vec3& normal,
                            const Vec3& slipVelocity, double normalForce, double dt) {
    const Vec3 tangentialSlip = slipVelocity - slipVelocity.dot(normal) * normal;
    if (law.regularisation != FrictionRegularisation::none) {
        // Eq. 2.65: against the slip, μ R(|v_t|) F_n; the spring stays at zero.
        const double slipSpeed = tangentialSlip.norm();
        if (!(slipSpeed > 0)) return Vec3::Zero();
        return -law.friction * std::max(0.0, normalForce) *
               regularisedFriction(law.regularisation, slipSpeed, law.regularisationSpeed) /
               slipSpeed * tangentialSlip;
    }
    // Rotate the stored displacement into the current tangent plane, keeping its length.
    Vec3& xi = spring.displacement;
    const double length = xi.norm();
    xi -= xi.dot(normal) * normal;
    const double projected = xi.norm();
    if (projected > 0) xi *= length / projected;
    xi += tangentialSlip * dt;

    const double stiffness = mindlinStiffness(pair, overlap);
    const double damping = dampingFactor(law) * std::sqrt(stiffness * pair.mass); // γ_t
    Vec3 force = -stiffness * xi - damping * tangentialSlip;

    // Coulomb limit (Eq. 2.14): scale the force down to μF_n and shorten the spring so that it
    // gives exactly that force at this slip velocity (the stick force resumes from there).
    const double limit = law.friction * std::max(0.0, normalForce); // a pulling dashpot: no grip
    const double magnitude = force.norm();
    if (magnitude > limit) {
        const double scale = magnitude > 0 ? limit / magnitude : 0.0;
        force *= scale;
        xi = -(force + damping * tangentialSlip) / stiffness;
    }
    return force;
}

double hertzMaxOverlap(const ContactPair& pair, double impactSpeed) {
    return std::pow(15.0 * pair.mass * impactSpeed * impactSpeed /
                        (16.0 * pair.youngsModulus * std::sqrt(pair.radius)),
                    0.4);
}

double hertzContactDuration(const ContactPair& pair, double impactSpeed) {
    // ∫₀¹ dx/√(1 − x^{5/2}) = (2/5) B(2/5, 1/2) = 1.47164...
    const double halfDurationFactor = 0.4 * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
    return 2.0 * halfDurationFactor * hertzMaxOverlap(pair, impactSpeed) / impactSpeed;
}

} // namespace slides
