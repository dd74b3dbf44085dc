// Soft-sphere contact: Hertz normal force with restitution damping, Mindlin tangential spring
// with history and Coulomb limit, and the Hertz contact duration that sets the time step.
//
// Reference: Section 2.2 of the reference: Eq. 2.4 (Hertz 1882: F = 4/3 E*√R* δ^{3/2},
// 1/R* = 1/R1 + 1/R2, 1/E* = (1−ν1²)/E1 + (1−ν2²)/E2), Eq. 2.5 (Mindlin 1949 tangential
// stiffness, 1/G* = (2−ν1)/G1 + (2−ν2)/G2), Eq. 2.6–2.8 (a damping term added to the elastic
// force, its constant fixed by the restitution coefficient e), Eq. 2.14 (Cundall & Strack 1979:
// tangential spring on the accumulated displacement, truncated at μ|F_n|); Eq. 2.59 (Hertz
// maximum overlap and contact duration). The forms are those of LIGGGHTS' `hertz` +
// `tangential history` model (Tsuji, Tanaka & Ishida 1992, Powder Technol. 71:239):
//   S_n = 2E*√(R*δ), k_n = 4/3 E*√(R*δ), S_t = 8G*√(R*δ), k_t = S_t,
//   γ_n = −2√(5/6) β √(S_n m*), γ_t = −2√(5/6) β √(S_t m*), β = ln e / √(ln²e + π²),
//   F_n = k_n δ + γ_n dδ/dt (clamped at 0: never attractive), F_t = −k_t ξ − γ_t v_t, |F_t| ≤ μF_n.
// A velocity Verlet step applies the damping γ dδ/dt as the difference of its potential
// Φ(δ) = ∫₀^δ γ over the window of its kicks, from the touch in a contact's first step
// (normalContactForce) and, for a force that may pull, to the parting in the step where the
// bodies come apart (partingNormalForce): second order in dt, where sampling γ at the half-step
// velocity is first.
// Eq. 2.5 as extracted reads K_t = (1/(8r_c))((2−ν1)/G1 + (2−ν2)/G2); Mindlin's stiffness is
// the inverse, K_t = 8 r_c G* with contact radius r_c = √(R*δ), as used here.
// The other normal laws of Eq. 2.6–2.10 (physics/contact_laws.h) and the regularised friction of
// Eq. 2.65–2.68 (physics/regularised_friction.h) are options of the same contact.
// A wall is a body of infinite radius and mass (and, if rigid, infinite moduli); the pair's
// effective properties are physics/contact_pair.h's.
//
//     particles { material { bulkModulus 1.6e11; shearModulus 8.0e10; } }   // E, ν from K, G
#pragma once

#include "slides/core/vector.h"
#include "slides/physics/contact_laws.h"
#include "slides/physics/contact_pair.h"
#include "slides/physics/regularised_friction.h"

#include <limits>

namespace slides {

/// The damping ratio β and Coulomb friction μ of a contact; the normal law and its constants
/// (physics/contact_laws.h), the friction's regularisation (physics/regularised_friction.h).
struct SoftContactLaw {
    double dampingRatio = 0; ///< β: 0 elastic, negative with damping (hertz)
    double friction = 0;     ///< μ
    NormalContactLaw normalLaw = NormalContactLaw::hertz;
    double normalStiffness = 0; ///< k (linearSpringDashpot), k_L (waltonBraun) [N/m]
    double restitution = 1;     ///< e of linearSpringDashpot and waltonBraun
    double dissipativeTime = 0; ///< Brilliantov's A (viscoelasticHertz) [s]
    FrictionRegularisation regularisation = FrictionRegularisation::none;
    double regularisationSpeed = 0; ///< ε of Eq. 2.66–2.68 [m/s]
};

/// LIGGGHTS' (Tsuji's) β = ln e / √(ln²e + π²). Exact for a linear spring-dashpot that may pull;
/// with Hertz stiffness and the no-pull clamp the impact restitutes more: e = 0.9 gives 0.9020,
/// e = 0.5 gives 0.5503, e = 0.2 gives 0.3249 (restitutionOfDampingRatio).
double liggghtsDampingRatio(double restitution);

/// Restitution coefficient of a damped Hertz impact with damping ratio β (independent of the
/// impact speed, radius, mass and moduli): the dimensionless impact x'' = −max(0, x^{3/2} +
/// κ x^{1/4} x'), κ = −√5 β, x(0) = 0, x'(0) = 1, integrated by RK4 (error < 1e-5) to x = 0.
double restitutionOfDampingRatio(double dampingRatio);

/// The law whose Hertz impacts restitute exactly e (0 < e ≤ 1): β solved from
/// restitutionOfDampingRatio by bisection (≈ 50 ms, once per material pair).
SoftContactLaw softContactLaw(double restitution, double friction);

/// Damping coefficient γ(δ) [N s/m] of the law at overlap δ > 0: its damping force is γ dδ/dt
/// (hertz: γ_n ∝ δ^{1/4}; linearSpringDashpot: 2ζ√(k m*); viscoelasticHertz: 3/2 K_n A √δ;
/// waltonBraun: 0).
double dampingCoefficient(const ContactPair& pair, const SoftContactLaw& law, double overlap);

/// The damping's potential Φ(δ) = ∫₀^δ γ [N s] (0 for δ ≤ 0): the damping force γ(δ) dδ/dt is
/// dΦ/dt, so its impulse over any interval is the difference of Φ at the interval's ends.
double dampingPotential(const ContactPair& pair, const SoftContactLaw& law, double overlap);

/// Normal force [N] on overlap δ > 0 closing at dδ/dt (Eq. 2.4 with the damping of Eq. 2.6–2.8:
/// k_n δ + γ_n dδ/dt), clamped at 0 so that the damping never pulls the bodies together.
double hertzNormalForce(const ContactPair& pair, const SoftContactLaw& law, double overlap,
                        double closingSpeed);

/// Normal force [N] of the law that a velocity Verlet step of length dt applies (its two half
/// kicks, over [t − dt/2, t + dt/2]) at overlap δ > 0, reached by a drift closing at dδ/dt: the
/// elastic force at δ, and the damping as its exact impulse over that window divided by dt, the
/// difference of dampingPotential at the window's ends (the overlap half a drift back, or the
/// touch if the contact began within the drift; half a drift ahead, at the closing speed this
/// force leaves, to first order in it). Sampling γ(δ) dδ/dt instead would be first order in dt:
/// γ_n grows as δ^{1/4} from the touch, and the half-step velocity lags. dt = 0 gives the law's
/// instantaneous force. Only the linear spring–dashpot may pull; Walton–Braun has no dashpot.
/// largestOverlap is the contact's δ_max so far, updated here (Walton–Braun's unloading
/// starts from it).
double normalContactForce(const ContactPair& pair, const SoftContactLaw& law, double overlap,
                          double closingSpeed, double dt, double& largestOverlap);

/// Whether the law's force may pull the bodies together: only the linear spring–dashpot's (its
/// closed form is the free damped oscillator's, whose last instants pull); the others are
/// clamped at 0.
inline bool mayPull(const SoftContactLaw& law) {
    return law.normalLaw == NormalContactLaw::linearSpringDashpot;
}

/// Normal force [N] that a step of length dt applies in the step where a contact parted (δ ≤ 0
/// now, > 0 at the last step), closing at dδ/dt: the dashpot's impulse from where the last
/// step's window ended (half a drift back) to the parting, Φ(0) − Φ(δ(t − dt/2)), over dt — the
/// window that normalContactForce's first step takes from the touch, at the other end. A force
/// clamped at 0 has ended before the parting (its dashpot outweighs the spring as δ → 0): 0
/// unless the law mayPull.
double partingNormalForce(const ContactPair& pair, const SoftContactLaw& law, double overlap,
                          double closingSpeed, double dt);

/// The conservative part of the law's normal force at overlap δ [N] (the loading curve of
/// Walton–Braun): what the force less it does is dissipated.
double elasticNormalForce(const ContactPair& pair, const SoftContactLaw& law, double overlap);

/// Duration of a head-on impact at speed v under the law [s]: Hertz's elastic duration
/// (hertz, viscoelasticHertz), π/ω_d (linearSpringDashpot), the time the force acts
/// (waltonBraun).
double softContactDuration(const ContactPair& pair, const SoftContactLaw& law, double impactSpeed);

/// Elastic energy 8/15 E*√R* δ^{5/2} [J] stored in a Hertz contact (the integral of Eq. 2.4).
double hertzElasticEnergy(const ContactPair& pair, double overlap);

/// The Mindlin/Cundall–Strack spring of one contact: its accumulated tangential displacement ξ.
/// Lives as long as the contact; a new contact starts from zero.
struct TangentialSpring {
    Vec3 displacement = Vec3::Zero(); ///< ξ [m], in the tangent plane
    /// δ_max of the contact so far [m] (waltonBraun); > 0 tells the step where the contact parts
    /// that it was touching.
    double largestOverlap = 0;
};

/// Mindlin's tangential stiffness k_t = S_t = 8 G* √(R* δ) [N/m] (Eq. 2.5, inverted).
double mindlinStiffness(const ContactPair& pair, double overlap);

/// Tangential force [N] on the first body (Eq. 2.5, 2.14): the spring is rotated into the
/// tangent plane of the current normal n (keeping its length), stretched by v_t dt, and the force
/// −k_t ξ − γ_t v_t truncated at μ F_n, the spring shortened to match (Cundall & Strack).
/// With a regularisation the spring is not used: −μ R(|v_t|) F_n v_t/|v_t| (Eq. 2.65–2.68).
/// slipVelocity is the first body's contact-point velocity relative to the second's.
Vec3 mindlinTangentialForce(TangentialSpring& spring, const ContactPair& pair,
                            const SoftContactLaw& law, double overlap, const Vec3& normal,
                            const Vec3& slipVelocity, double normalForce, double dt);

/// Largest overlap of an elastic Hertz impact at normal speed v: (15 m* v² / (16 E*√R*))^{2/5}
/// (Eq. 2.59).
double hertzMaxOverlap(const ContactPair& pair, double impactSpeed);

/// Duration of an elastic Hertz impact [s]: 2 δ_max/v ∫₀¹ dx/√(1 − x^{5/2}) = 2.9432 δ_max/v,
/// i.e. 2.87 (m*²/(R* E*² v))^{1/5} of Eq. 2.59.
double hertzContactDuration(const ContactPair& pair, double impactSpeed);

/// Time step resolving a Hertz impact at speed v with the given number of steps per contact.
inline double softContactStep(const ContactPair& pair, double impactSpeed,
                              double stepsPerContact = 50) {
    return hertzContactDuration(pair, impactSpeed) / stepsPerContact;
}

} // namespace slides
