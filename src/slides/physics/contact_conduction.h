// Conduction between touching particles: the heat that flows through the gas-filled gap
// around the point where two hot and cold spheres touch (Batchelor & O'Brien), exchanged by the
// soft-sphere contacts while they last.
//
// Reference: Section 2.8.2 of the reference, Eq. 2.118 (Batchelor & O'Brien 1977, Proc. R. Soc.
// Lond. A 355:313, for conductivity ratio α = K_p/K_f ≫ 1):
//   Q = π K_f a (T₀ − T₁) ln α²,
// with a the spheres' radius. The flux crosses the gas where the gap h(r) = r²/(2R*) is thin,
// between r ~ a/α and r ~ a: ∫ K_f ΔT 2πr dr / h = 4π K_f R* ΔT ln α, so for unequal spheres
// a = 2R* (the reference's "effective radius" R is the sphere radius of equal spheres). Unlike
// spheres conduct through 1/K_p = 1/K_p1 + 1/K_p2 (Zhou et al., Section 2.8.2) — one material
// here: K_p. The conductance is zero where α ≤ 1 (the formula holds for α ≫ 1 only).
// The heat is exchanged over each step with the temperatures at its start (explicit): one pair's
// two flows are equal and opposite, so Σ m c T is conserved to round-off; the step must stay
// well below m c/H (the pair relaxes as exp(−H (1/(m₁c) + 1/(m₂c)) t)).
//
//     collisions { conduction batchelorOBrien; }   // particles { thermalConductivity 30; }
#pragma once

#include <array>
#include <cmath>
#include <numbers>
#include <string_view>

namespace slides {

enum class ContactConduction { none, batchelorOBrien };

struct ContactConductionName {
    ContactConduction value;
    std::string_view name;
};

// How to add a model: an enumerator, its name here, its case in contactConductance.
constexpr std::array<ContactConductionName, 2> contactConductionNames() {
    return {{{ContactConduction::none, "none"},
             {ContactConduction::batchelorOBrien, "batchelorOBrien"}}};
}

struct ContactConductionSettings {
    ContactConduction model = ContactConduction::none;
    double particleConductivity = 0; ///< K_p [W/(m K)]
    double gasConductivity = 0;      ///< K_f [W/(m K)]
};

/// Conductance H [W/K] of a touching pair of effective radius R*: the heat flow into the
/// first body is H (T₂ − T₁) (Eq. 2.118 with a = 2R*).
inline double contactConductance(const ContactConductionSettings& settings,
                                 double effectiveRadius) {
    switch (settings.model) {
    case ContactConduction::none: return 0.0;
    case ContactConduction::batchelorOBrien: {
        const double ratio = settings.particleConductivity / settings.gasConductivity; // α
        if (!(ratio > 1)) return 0.0;
        return std::numbers::pi * settings.gasConductivity * 2 * effectiveRadius *
               std::log(ratio * ratio);
    }
    }
    return 0.0;
}

} // namespace slides
