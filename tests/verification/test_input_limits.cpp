// ctest-labels: robustness run
// Parseable values past any real case, which once ended in an internal error, a hang or an
// allocation failure, some after writing files: each is refused with exit status 2 and one
// message naming its key before the output directory exists. The bounds are those of the key
// table (config/scene_keys.cpp), the step and frame limits of run/run_limits.h, the machine's
// memory, and the nozzle disc or lattice inside the domain box (run/injection_check.h).
#include "../support/broken_cases.h"

#include <gtest/gtest.h>

namespace slides {
namespace {

const test::BrokenCase limitCases[] = {
    {"densityPastAnyMaterial", "    density     5680;", "    density     1e308;", 0,
     "key 'particles.density': must be at most 100000"},
    {"radiusPastAnyParticle", "        value   80e-6;", "        value   1e308;", 0,
     "key 'particles.radiusDistribution.value': must be at most 1"},
    {"nozzleVelocityPastAnyJet", "        nozzleVelocity  25;", "        nozzleVelocity  1e308;", 0,
     "key 'carrier.analyticJetCoeffs.nozzleVelocity': must be at most 10000"},
    // 1e12 particles of at least 64 bytes each: 6.4e13 bytes, more than any machine here.
    {"particlesPastTheMemory", "    count       8000;", "    count       1000000000000;", 0,
     "key 'particles.count': 1000000000000 particles need at least 6.4e+13 bytes, more than the "
     "machine's memory"},
    // 1e15 grid points of at least 48 bytes each.
    {"carrierGridPastTheMemory", "    carrierResolution   (141 61 61);",
     "    carrierResolution   (100000 100000 100000);", 0,
     "key 'output.carrierResolution': the carrier grid's 100000×100000×100000 points need at "
     "least 4.8e+16 bytes, more than the machine's memory"},
    // The parabola U(1 − y²/h²) at the domain's y = ±0.03 m: infinite for h = 1e-300.
    {"channelNarrowerThanAnyFlow", "    type        analyticJet;",
     "    type        planePoiseuille;\n"
     "    planePoiseuilleCoeffs { centrelineVelocity 1; halfWidth 1e-300; }",
     1, "key 'carrier.planePoiseuilleCoeffs.halfWidth': the gas speed U|1 − y²/h²| reaches inf"},
    // A cut-off of 1e-300 m makes the pair search's cells past any count (collide/cell_grid.h).
    {"coulombCutoffBelowAnyParticle", "    gravity     (0 -9.81 0);",
     "    gravity     (0 -9.81 0);\n"
     "    electromagnetic { model lorentz; coulomb { model shifted; cutoff 1e-300; } }",
     1, "key 'physics.electromagnetic.coulomb.cutoff': must be at least 1e-09"},
    {"oppositeSignFractionAboveOne", "    gravity     (0 -9.81 0);",
     "    gravity     (0 -9.81 0);\n"
     "    electromagnetic { model lorentz; charge { value 1e-15; oppositeSignFraction 1.5; } }",
     1,
     "key 'physics.electromagnetic.charge.oppositeSignFraction': must lie in [0, 1] (a fraction "
     "of the particles)"},
    {"permittivityBelowTheVacuums", "    gravity     (0 -9.81 0);",
     "    gravity     (0 -9.81 0);\n"
     "    electromagnetic { model lorentz; coulomb { model shifted; permittivity 0.5; } }",
     1, "key 'physics.electromagnetic.coulomb.permittivity': must be at least 1"},
    {"historyAccuracyPastDoublePrecision", "    drag        haiderLevenspiel;",
     "    drag        haiderLevenspiel;\n    history { model basset; accuracy 1e-300; }", 1,
     "key 'physics.history.accuracy': must be at least 1e-10"},
    // endTime 0.1 s over the interval and the step.
    {"radiusSpreadPastAnyParticle", "        type    fixed;\n        value   80e-6;",
     "        type    normal;\n        mean    80e-6;\n        standardDeviation 1e308;", 2,
     "key 'particles.radiusDistribution.standardDeviation': must be at most 1"},
    {"radiusMinimumPastAnyParticle", "        value   80e-6;",
     "        value   80e-6;\n        minimum 1e308;", 1,
     "key 'particles.radiusDistribution.minimum': must be at most 1"},
    {"radiusMaximumPastAnyParticle", "        value   80e-6;",
     "        value   80e-6;\n        maximum 1e308;", 1,
     "key 'particles.radiusDistribution.maximum': must be at most 1"},
    {"framesPastTheLimit", "    interval            5e-4;", "    interval            1e-300;", 0,
     "key 'output.interval': gives 1e+299 frames to time.endTime 0.1 s, more than the 1e+06 a "
     "run may write"},
    {"stepsPastTheLimit", "    dt              1e-5;", "    dt              1e-12;", 0,
     "key 'time.dt': gives 1e+11 steps to time.endTime 0.1 s, more than the 1e+09 a run may "
     "take"},
    // A disc of radius 0.04 m about the centre of a domain 0.06 m across: its parts beyond
    // |y| or |z| = 0.03 m, 29 % of its area, hold 140 of the 512 points.
    {"nozzleDiscPastTheDomainBox", "    radius      2e-3;", "    radius      0.04;", 0,
     "key 'nozzle.radius': the nozzle disc of radius 0.04 m is not inside the domain box: 27 % "
     "of it (140 of 512 points spread evenly over it) lies outside"},
    // Sites 1 mm apart from x = 0.0605 m: 5 of the 20 planes of 400 sites lie before the
    // domain's end at x = 0.065 m, the other 6000 sites beyond it.
    {"latticePastTheDomainBox", "    mode            rate;",
     "    mode            lattice;\n    latticeCoeffs { origin (0.06 0 0); spacing 1e-3; sites (20 "
     "20 20); }",
     1,
     "key 'injection.latticeCoeffs.origin': the lattice of 8000 sites is not inside the domain "
     "box: 75 % of it (6000 of 8000 points spread evenly over it) lies outside"},
};

using test::RefusedCase;
INSTANTIATE_TEST_SUITE_P(InputLimits, RefusedCase, ::testing::ValuesIn(limitCases),
                         test::brokenCaseName);

} // namespace
} // namespace slides
