// ctest-labels: foundation config
// The name table of every model family (DESIGN.md: one table per family): each name selects
// its own value and each value prints as its own name, so the dictionary, the summary and
// the README agree; a name outside the table selects nothing.
#include "slides/core/name_table.h"
#include "slides/integrate/integrator.h"
#include "slides/io/particle_fields.h"
#include "slides/physics/drag.h"

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

TEST(NameTables, DragLaws) { expectRoundTrip(dragModelNames()); }
TEST(NameTables, Integrators) { expectRoundTrip(integratorNames()); }
TEST(NameTables, ParticleFields) { expectRoundTrip(particleFieldNames()); }

} // namespace
} // namespace slides
