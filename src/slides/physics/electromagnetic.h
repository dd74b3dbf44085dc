// Electromagnetic forces on charged particles: the Lorentz force F = q (E + v × B) (Eq. 2.93)
// in uniform applied fields, the particle a lumped charge at its centre (Section 2.7.1).
//
// Reference: Section 2.7.1, Eq. 2.93. A particle's charge is fixed (the same q for every
// particle) or proportional to its surface, q = σ 4πR² (a surface charge density σ, as
// triboelectric and corona charging give); a fraction of the particles may carry the opposite
// sign (bipolar charging, as tribocharging of a powder against itself gives), each particle's
// sign drawn from its id. Per unit mass the force is g_E + v × Ω with
// g_E = qE/m and the signed gyration vector Ω = qB/m (|Ω| the cyclotron frequency, Larmor radius
// |v⊥|/|Ω|); integrate/lorentz_flow.h integrates it exactly together with the drag. The charged
// particles' Coulomb forces on each other (Eq. 2.94–2.97) are physics/coulomb.h's.
//
// B is the uniform B plus the fields of any coils (circular current loops, physics/current_loop.h).
// A linear magnetisable particle (susceptibility χm, Eq. 2.107–2.110) in such a field also feels
// F/m = χm/(µ0 µr ρp) (∇B)ᵀ B (physics/magnetic_force.h), charged or not.
//
//     physics { electromagnetic { model lorentz;            // none | lorentz
//                                 E (0 0 1e5);               // V/m
//                                 B (0 0 0.5);               // T
//                                 charge { model surface; value 1e-5;   // fixed: C; surface: C/m²
//                                          oppositeSignFraction 0.3; }
//                                 coils { a { centre (0 0 0); axis (0 0 1); radius 0.05;
//                                             current 2000; } }
//                                 magnetisation { model linear; susceptibility 0.5; } } }
//
// How to add a charge model: an enumerator, its name in chargeModelNames() and its case in
// ElectromagneticSettings::chargeOfModel().
#pragma once

#include "slides/core/particle_cloud.h"
#include "slides/core/random.h"
#include "slides/core/vector.h"
#include "slides/physics/coulomb.h"
#include "slides/physics/current_loop.h"
#include "slides/physics/magnetic_force.h"

#include <array>
#include <numbers>
#include <string_view>
#include <vector>

namespace slides {

enum class ElectromagneticModel { none, lorentz };

struct ElectromagneticModelName {
    ElectromagneticModel value;
    std::string_view name;
};

/// The name table of the electromagnetic family, as written in the dictionary.
constexpr std::array<ElectromagneticModelName, 2> electromagneticModelNames() {
    return {{{ElectromagneticModel::none, "none"}, {ElectromagneticModel::lorentz, "lorentz"}}};
}

enum class ChargeModel { fixed, surface };

struct ChargeModelName {
    ChargeModel value;
    std::string_view name;
};

/// The name table of the particle charge: fixed q [C], or surface density σ [C/m²].
constexpr std::array<ChargeModelName, 2> chargeModelNames() {
    return {{{ChargeModel::fixed, "fixed"}, {ChargeModel::surface, "surface"}}};
}

enum class MagnetisationModel { none, linear };

struct MagnetisationModelName {
    MagnetisationModel value;
    std::string_view name;
};

/// The name table of the particles' magnetisation: none, or linear M = χm H (Eq. 2.107).
constexpr std::array<MagnetisationModelName, 2> magnetisationModelNames() {
    return {{{MagnetisationModel::none, "none"}, {MagnetisationModel::linear, "linear"}}};
}

struct ElectromagneticSettings {
    ElectromagneticModel model = ElectromagneticModel::none;
    Vec3 electricField = Vec3::Zero(); ///< E [V/m]
    Vec3 magneticField = Vec3::Zero(); ///< B [T]
    ChargeModel charge = ChargeModel::fixed;
    double chargeValue = 0; ///< q [C] (fixed) or σ [C/m²] (surface)
    /// The expected fraction of particles whose charge has the sign opposite to chargeValue's.
    double oppositeSignFraction = 0;
    std::uint64_t seed = 0;         ///< of the signs' draws (injection.seed)
    CoulombSettings coulomb;        ///< the particles' forces on each other (physics/coulomb.h)
    std::vector<CurrentLoop> coils; ///< their fields join the uniform B
    /// The particles' χm is theirs (ParticleSettings::susceptibility, ParticleSpecies).
    MagnetisationModel magnetisation = MagnetisationModel::none;

    bool on() const { return model != ElectromagneticModel::none; }
    /// Whether E and B are the same everywhere (no coils).
    bool uniform() const { return coils.empty(); }
    bool magnetisable() const { return magnetisation != MagnetisationModel::none; }

    /// B and ∇B at x: the uniform B and every coil's field.
    MagneticFieldSample magneticFieldAt(const Vec3& x) const {
        MagneticFieldSample sum;
        sum.field = magneticField;
        for (const CurrentLoop& coil : coils) {
            const MagneticFieldSample loop = loopField(coil, x);
            sum.field += loop.field;
            sum.gradient += loop.gradient;
        }
        return sum;
    }

    /// The charge of particle id of the given radius [C]: its sign drawn from (seed, id), so the
    /// same on any thread, rank or restart.
    double chargeOf(double radius, ParticleId id) const {
        const double q = chargeOfModel(radius);
        if (oppositeSignFraction == 0) return q;
        RandomStream random(seed, id, RandomPurpose::chargeSign);
        return random.uniform() < oppositeSignFraction ? -q : q;
    }

    /// The charge model's charge of a particle of the given radius [C], before its sign draw.
    double chargeOfModel(double radius) const {
        switch (charge) {
        case ChargeModel::fixed: return chargeValue;
        case ChargeModel::surface: return chargeValue * 4 * std::numbers::pi * radius * radius;
        }
        return chargeValue;
    }
};

/// The Lorentz force of Eq. 2.93 per unit mass, split as the flow takes it: the electric
/// acceleration qE/m and the gyration vector Ω = qB/m (dv/dt = qE/m + v × Ω).
struct LorentzRates {
    Vec3 electricAcceleration; ///< qE/m [m/s²]
    Vec3 gyration;             ///< Ω = qB/m [rad/s]
};

} // namespace slides
