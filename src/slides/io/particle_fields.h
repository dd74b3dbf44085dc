// ParticleField: the point arrays a particle frame (.vtp) can carry, chosen by
// `output { fields (id diameter velocity speed state temperature angularVelocity); }` (default:
// all of them; temperature exists only with heat transfer, physics/heat_transfer.h, and
// angularVelocity only where the particles carry a spin, surfaces/surface_settings.h tracksSpin).
#pragma once

#include <array>
#include <bitset>
#include <string_view>

namespace slides {

enum class ParticleField { id, diameter, velocity, speed, state, temperature, angularVelocity };

struct ParticleFieldName {
    ParticleField value;
    std::string_view name;
};

constexpr std::array<ParticleFieldName, 7> particleFieldNames() {
    return {{{ParticleField::id, "id"},
             {ParticleField::diameter, "diameter"},
             {ParticleField::velocity, "velocity"},
             {ParticleField::speed, "speed"},
             {ParticleField::state, "state"},
             {ParticleField::temperature, "temperature"},
             {ParticleField::angularVelocity, "angularVelocity"}}};
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

/// The fields of `asked` that a frame has: temperature only with heating, ω only with spin.
inline ParticleFieldSet presentFields(ParticleFieldSet asked, bool heating, bool spinning) {
    if (!heating) asked = asked.without(ParticleField::temperature);
    if (!spinning) asked = asked.without(ParticleField::angularVelocity);
    return asked;
}

} // namespace slides
