// The gas velocity of the sech² jet (Eq. 5.10/5.11, carrier/analytic_jet.h) over a batch of
// points in SIMD lanes: Highway, dispatched at run time, with its vector expm1, exp and log.
//
// The same U as JetFrame::sample with BickleyProfile::at (the scalar reference, which also
// gives ∇U): behind the exit plane at rest, the frozen core, the self-similar jet; each point
// one lane, the last partial vector padded, so a point's value does not depend on the batch or
// the thread count. tests/unit/test_vector_kernels.cpp holds the two within 1e-13 relative.
//
//     carrier { type analyticJet; analyticJetCoeffs { profile axisymmetric; ... } }
#pragma once

#include "slides/carrier/analytic_jet.h"

#include <span>

namespace slides {

/// velocity[i] = U(points[i]) of the jet of frame and profile; velocity has points' size.
void sampleBickleyVelocity(const JetFrame& frame, const BickleyProfile& profile,
                           std::span<const Vec3> points, std::span<Vec3> velocity);

} // namespace slides
