// ParticleField: the point arrays a particle frame (.vtp) can carry, chosen by
// `output { fields (id diameter velocity speed state temperature); }` (default: all of them;
// temperature exists only with heat transfer, physics/heat_transfer.h).
#pragma once

#include <array>
#include <bitset>
#include <string_view>

namespace slides {

enum class ParticleField { id, diameter, velocity, speed, state, temperature };

struct ParticleFieldName {
    ParticleField value;
    std::string_view name;
};

constexpr std::array<ParticleFieldName, 6> particleFieldNames() {
    return {{{ParticleField::id, "id"},
             {ParticleField::diameter, "diameter"},
             {ParticleField::velocity, "velocity"},
             {ParticleField::speed, "speed"},
             {ParticleField::state, "state"},
             {ParticleField::temperature, "temperature"}}};
}

/// A subset of the particle fields.
class ParticleFieldSet {
public:
    static ParticleFieldSet all() {
        ParticleFieldSet every;
        every.bits_.set();
        return every;
    }
    ParticleFieldSet& add(ParticleField field) {
        bits_.set(static_cast<std::size_t>(field));
        return *this;
    }
    bool contains(ParticleField field) const { return bits_.test(static_cast<std::size_t>(field)); }
    ParticleFieldSet without(ParticleField field) const {
        ParticleFieldSet rest = *this;
        rest.bits_.reset(static_cast<std::size_t>(field));
        return rest;
    }

private:
    std::bitset<particleFieldNames().size()> bits_;
};

} // namespace slides
