// Unsteady heat transfer of Michaelides & Feng: conduction, the fluid's heat capacity and the
// history of the particle–fluid temperature difference, the energy analogue of Maxey–Riley.
//
// Reference: Eq. 3.29 of the reference; Michaelides & Feng (1994, J. Heat Transfer 116:305,
// "Heat transfer from a rigid sphere in a nonuniform flow and temperature field"):
//   m_p c_p dθp/dt = m_f c_f Dθf/Dt − 4πR K_f (θp − θf − (R²/6)∇²θf)
//                    − 4πR² K_f ∫_0^t d/dτ(θp − θf − (R²/6)∇²θf) / √(π κ_f (t − τ)) dτ,
// κ_f = K_f/(ρf c_f). The conduction term is Nu = 2 (physics/heat_transfer.h); the history kernel
// is Basset's 1/√(t − τ), so with the difference s = θf − θp per unit particle heat capacity
//   dθp/dt = (ρf c_f/ρp c_p) dθf/dt + s/τ_θ + r_T d/dt ∫_0^t s(τ)/√(t − τ) dτ,
//   1/τ_θ = 3 K_f/(ρp c_p R²),   r_T = 3 K_f/(ρp c_p R √(π κ_f)),
// the form of the Basset step (physics/history_integrator.h: window + exponential-sum tail, the
// start mode of a particle released at another temperature than the gas); d/dt ∫ carries the
// jump at release, the sudden √(κ_f t) conduction layer. Every carrier's θf is uniform or linear
// in each tetrahedron, so ∇²θf = 0 and the Faxén term drops. The fluid-capacity term is taken
// along the particle's path, where it is a total derivative: θp gains (ρf c_f/ρp c_p) Δθf over a
// step in which the gas temperature it sees changes by Δθf (D/Dt would differ by (u − v)·∇θf).
//
//     physics { heatTransfer { model michaelidesFeng; } history { accuracy 1e-3; } }
#pragma once

#include "slides/physics/history_integrator.h"

namespace slides {

/// The rates of Eq. 3.29 per unit particle heat capacity.
struct MichaelidesFengRates {
    double conductionRate = 0;     ///< 1/τ_θ = 3 K_f/(ρp c_p R²) [1/s] (Nu = 2)
    double historyRate = 0;        ///< r_T = 3 K_f/(ρp c_p R √(π κ_f)) [1/√s]
    double fluidCapacityRatio = 0; ///< ρf c_f/(ρp c_p)
};

MichaelidesFengRates michaelidesFengRates(double particleDensity, double particleSpecificHeat,
                                          double particleRadius, double fluidDensity,
                                          double fluidSpecificHeat,
                                          double fluidThermalConductivity);

/// Doubles of a particle's state: age, the gas temperature of the last step, the start
/// difference s0 and I_n (three each, as the history step keeps them), and the memory.
inline std::size_t michaelidesFengDoubles(const WindowTailLayout& layout) {
    return 8 + layout.doubles();
}

/// θp after a step of h in gas at temperature gasTemperature (frozen over the step); state holds
/// michaelidesFengDoubles(layout) doubles, all zero for a particle not yet stepped.
double advanceMichaelidesFeng(const MichaelidesFengRates& rates, const WindowTailLayout& layout,
                              double* state, double temperature, double gasTemperature, double h);

} // namespace slides
