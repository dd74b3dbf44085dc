// Physics settings: the forces and models of the particle equation of motion (`physics {}`),
// each chosen through its family's name table (physics/drag.h, history_integrator.h, lift.h,
// dispersion.h, heat_transfer.h); `auto` leaves a term to the scene analysis.
//
//     physics { drag haiderLevenspiel; gravity (0 0 -9.81); buoyancy on;
//               history { model auto; accuracy 1e-3; } addedMass auto; pressureGradient auto;
//               lift auto; spin auto; dispersion { model auto; } heatTransfer { model auto; }
//               autoThreshold 0.01; }
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/core/vector.h"
#include "slides/physics/dispersion.h"
#include "slides/physics/drag.h"
#include "slides/physics/electromagnetic.h"
#include "slides/physics/heat_transfer.h"
#include "slides/physics/history_integrator.h"
#include "slides/physics/lift.h"
#include "slides/physics/physics_term.h"

#include <vector>

namespace slides {

struct PhysicsSettings {
    DragModel drag = DragModel::haiderLevenspiel;
    Vec3 gravity = Vec3::Zero(); ///< [m/s²]
    bool buoyancy = true;
    // Unsteady terms (integrate/maxey_riley.h); all off by default.
    HistoryModel history = HistoryModel::none;
    double historyAccuracy = 1e-3; ///< relative error target of the history kernel's tail
    bool addedMass = false;
    bool pressureGradient = false;
    LiftModel lift = LiftModel::none;
    bool spin = false;
    bool spinHistory = false; ///< the unsteady torque of Eq. 3.19 (needs spin)
    bool faxen = false;       ///< Faxén terms of Eq. 3.2 (physics/faxen.h; needs ∇²U)
    DispersionModel dispersion = DispersionModel::none; ///< physics/dispersion.h
    DispersionConstants dispersionConstants;
    HeatTransferModel heatTransfer = HeatTransferModel::none; ///< physics/heat_transfer.h
    ElectromagneticSettings electromagnetic;                  ///< physics/electromagnetic.h
    /// Terms left to the scene analysis (`auto`), off until it turns them on.
    std::vector<AutomaticTerm> automaticTerms;
    /// Largest estimated effect of a term that auto turns off (analysis/scene_analysis.h).
    double autoThreshold = 0.01;

    /// Whether any unsteady term (or the Faxén terms) is on: then the Maxey–Riley step replaces
    /// the integrator.
    bool unsteadyForces() const {
        return history != HistoryModel::none || addedMass || pressureGradient ||
               lift != LiftModel::none || spin || faxen;
    }
    /// What the terms ask of the carrier beside U: k and ε for dispersion, T for heat transfer
    /// (∇U is the Maxey–Riley step's, integrate/maxey_riley.h).
    CarrierNeeds carrierNeeds() const {
        return {.turbulence = dispersion != DispersionModel::none,
                .temperature = heatTransfer != HeatTransferModel::none};
    }
};

} // namespace slides
