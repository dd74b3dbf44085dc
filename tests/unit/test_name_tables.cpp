// ctest-labels: foundation config
// The name table of every model family (DESIGN.md: one table per family): each name selects
// its own value and each value prints as its own name, so the dictionary, the summary and
// the README agree; a name outside the table selects nothing.
#include "slides/carrier/carrier_settings.h"
#include "slides/carrier/foam_interpolation.h"
#include "slides/collide/collision_settings.h"
#include "slides/core/name_table.h"
#include "slides/integrate/injection_settings.h"
#include "slides/integrate/integrator.h"
#include "slides/io/particle_fields.h"
#include "slides/physics/adhesion.h"
#include "slides/physics/coulomb.h"
#include "slides/physics/dispersion.h"
#include "slides/physics/drag.h"
#include "slides/physics/heat_transfer.h"
#include "slides/physics/history_integrator.h"
#include "slides/physics/lift.h"
#include "slides/physics/physics_term.h"
#include "slides/physics/restitution.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace slides {
namespace {

template <typename Table> void expectRoundTrip(const Table& table) {
    std::set<std::string_view> names;
    for (const auto& entry : table) {
        EXPECT_TRUE(names.insert(entry.name).second) << "name listed twice: " << entry.name;
        ASSERT_TRUE(valueNamed(table, entry.name).has_value()) << entry.name;
        EXPECT_EQ(*valueNamed(table, entry.name), entry.value) << entry.name;
        EXPECT_EQ(nameOf(table, entry.value), entry.name);
    }
    EXPECT_FALSE(valueNamed(table, "none of these").has_value());
}

TEST(NameTables, CarrierTypes) { expectRoundTrip(carrierTypeNames()); }
TEST(NameTables, JetProfiles) { expectRoundTrip(jetGeometryNames()); }
TEST(NameTables, TurbulenceScalings) { expectRoundTrip(turbulenceScalingNames()); }
TEST(NameTables, FoamInterpolations) { expectRoundTrip(foamInterpolationNames()); }
TEST(NameTables, RadiusDistributions) { expectRoundTrip(radiusDistributionNames()); }
TEST(NameTables, InjectionModes) { expectRoundTrip(injectionModeNames()); }
TEST(NameTables, InjectionModels) { expectRoundTrip(injectionModelNames()); }
TEST(NameTables, PackingMethods) { expectRoundTrip(packingMethodNames()); }
TEST(NameTables, PackingShapes) { expectRoundTrip(packingShapeNames()); }
TEST(NameTables, DragLaws) { expectRoundTrip(dragModelNames()); }
TEST(NameTables, HistoryModels) { expectRoundTrip(historyModelNames()); }
TEST(NameTables, LiftModels) { expectRoundTrip(liftModelNames()); }
TEST(NameTables, DispersionModels) { expectRoundTrip(dispersionModelNames()); }
TEST(NameTables, HeatTransferModels) { expectRoundTrip(heatTransferModelNames()); }
TEST(NameTables, CoulombModels) { expectRoundTrip(coulombModelNames()); }
TEST(NameTables, PhysicsTerms) { expectRoundTrip(physicsTermNames()); }
TEST(NameTables, Integrators) { expectRoundTrip(integratorNames()); }
TEST(NameTables, CollisionModels) { expectRoundTrip(collisionModelNames()); }
TEST(NameTables, RestitutionModels) { expectRoundTrip(restitutionModelNames()); }
TEST(NameTables, SoftSphereDampings) { expectRoundTrip(softSphereDampingNames()); }
TEST(NameTables, SurfaceInteractions) { expectRoundTrip(surfaceInteractionNames()); }
TEST(NameTables, AdhesionModels) { expectRoundTrip(adhesionModelNames()); }
TEST(NameTables, ParticleFields) { expectRoundTrip(particleFieldNames()); }

} // namespace
} // namespace slides
