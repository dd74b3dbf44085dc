// Injection settings: the particles (`particles {}`) and how they enter (`injection {}`), with
// the name tables of the radius distributions and injection modes.
//
//     particles { count 8000; density 2500;
//                 radiusDistribution { type logNormal; median 5e-6; geometricStandardDeviation 1.5;
//                                      minimum 1e-6; maximum 2e-5; } }
//     injection { mode rate; rate 8e4; crossSpanSpeed 0.5; seed 1; }
//               // or: mode lattice; latticeCoeffs { origin (0 0 0); spacing 1e-4;
//               //                                   sites (10 10 10); velocitySpread 0.1; }
//
//     injectors                    // several injectors instead of nozzle + injection
//     {
//         gunA { model disc; centre (0 0 0); axis (1 0 0); radius 2e-3; count 4000; rate 8e4; }
//         gunB { model cone; centre (0 0.02 0); axis (1 -0.2 0); count 2000; rate 4e4;
//                coneCoeffs { innerHalfAngle 10; outerHalfAngle 20; speed 30; }
//                density 8960; material { bulkModulus 140e9; } }  // its own species
//         rows { model file; file "constant/particles.csv"; }     // integrate/particle_file.h
//         fromA { model file; file "../runA/slides/particles.h5";
//                 fileCoeffs { source frame; time 2e-3; } }
//         bed { model file; file "constant/kinematicCloudPositions";
//               fileCoeffs { velocity (0 -1 0); } }
//         inlet { model patch; patchCoeffs { patch inlet; } count 1000; rate 1e5; }
//         bed { model ensemble; count 500; ensembleCoeffs { ... } }  // integrate/ensemble.h
//     }
//
// How to add a mode, model or distribution: an enumerator, its name in its table below, its key
// rows in config/scene_keys.cpp and its case in integrate/injector.cpp (radii:
// integrate/size_distribution.cpp).
#pragma once

#include "slides/carrier/jet_frame.h"
#include "slides/core/vector.h"
#include "slides/integrate/ensemble.h"
#include "slides/physics/contact_pair.h"

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace slides {

enum class RadiusDistributionKind { fixed, normal, logNormal, rosinRammler, table };

struct RadiusDistributionName {
    RadiusDistributionKind value;
    std::string_view name;
};

constexpr std::array<RadiusDistributionName, 5> radiusDistributionNames() {
    return {{{RadiusDistributionKind::fixed, "fixed"},
             {RadiusDistributionKind::normal, "normal"},
             {RadiusDistributionKind::logNormal, "logNormal"},
             {RadiusDistributionKind::rosinRammler, "rosinRammler"},
             {RadiusDistributionKind::table, "table"}}};
}

/// What a distribution's parameters describe: the number of particles of each size, or their
/// mass (users quote mass-median diameters). Particles are always drawn one by one, so a mass
/// distribution is sampled as the number distribution it implies, f_n(r) ∝ f_m(r)/r³.
enum class SizeWeighting { number, mass };

struct SizeWeightingName {
    SizeWeighting value;
    std::string_view name;
};

constexpr std::array<SizeWeightingName, 2> sizeWeightingNames() {
    return {{{SizeWeighting::number, "number"}, {SizeWeighting::mass, "mass"}}};
}

struct RadiusDistribution {
    RadiusDistributionKind kind = RadiusDistributionKind::fixed;
    double value = 0;                      ///< fixed radius [m]
    double mean = 0;                       ///< normal: mean radius [m]
    double standardDeviation = 0;          ///< normal [m]
    double median = 0;                     ///< logNormal: median radius [m]
    double geometricStandardDeviation = 1; ///< logNormal: e^σ of ln R (≥ 1)
    double minimum = 0;                    ///< draws below are redrawn [m]
    double maximum = 0;                    ///< draws above are redrawn [m]
    double scale = 0;  ///< rosinRammler: r̄ of F(r) = 1 − exp(−(r/r̄)^n) [m]
    double spread = 0; ///< rosinRammler: n
    SizeWeighting weighting = SizeWeighting::number;
    /// table: radii [m], ascending, and the cumulative fraction below each (0 … 1), linear
    /// between them (the number, or with mass weighting the mass, uniform in r).
    std::vector<double> tableRadius, tableCumulative;
    /// Expected value of the (untruncated) distribution [m]: the one "mean radius" of a run
    /// (its Stokes time, the scene analysis, the summary).
    double meanRadius() const;
};

/// What a particle is made of, where injectors differ (`injectors.NAME.density`, `.material`,
/// `.specificHeat`, `.susceptibility`; what an injector does not give is the particles' own).
struct ParticleSpecies {
    double density = 0; ///< ρp [kg/m³]
    MaterialSettings material;
    double specificHeat = 0;   ///< c_p [J/(kg K)]
    double susceptibility = 0; ///< χm [-], magnetisation
    bool operator==(const ParticleSpecies&) const = default;
};

/// The particle ids of a run's injectors: injector j's own block [firstIds[j], firstIds[j + 1])
/// (the last up to total), and past all blocks its re-injected particles, interleaved:
/// the m-th particle injector j re-injects takes id total + J·m + j (J injectors). An id so
/// names its injector without a table, and each injector's re-injected ids depend only on its
/// own count, not on the order of escapes.
struct InjectorIds {
    std::vector<std::uint64_t> firstIds; ///< ascending
    std::uint64_t total = 0;             ///< the particles of all blocks
    /// The index of the injector particle id came from.
    std::int32_t injectorOf(std::uint64_t id) const;
    /// The id of the m-th particle injector re-injects.
    std::uint64_t reinjectedId(std::size_t injector, std::uint64_t m) const {
        return total + firstIds.size() * m + injector;
    }
};

struct ParticleSettings {
    long count = 0;
    double density = 0; ///< ρp [kg/m³]
    RadiusDistribution radius;
    MaterialSettings material;
    double specificHeat = 0;         ///< c_p [J/(kg K)], heat transfer
    double thermalConductivity = 0;  ///< K_p [W/(m K)], for the Biot number; 0: not given
    double injectionTemperature = 0; ///< θ at injection [K], heat transfer
    /// χm [-] with physics.electromagnetic.magnetisation (its susceptibility, or the first
    /// injector's).
    double susceptibility = 0;
    /// Particle species where injectors, or the rows of a file injector, differ in what their
    /// particles are made of: empty when every particle is alike (the values above, and nothing
    /// costs more); else one entry each distinct species, species[0] the first injector's (its
    /// first row's; also the values above). A particle's species follows from its id (its
    /// injector, through speciesOfInjector, or its row there, through speciesOfRow), so it moves
    /// with the id through sorting, removal, the deposit, checkpoints and ranks without an array
    /// of its own.
    std::vector<ParticleSpecies> species;
    std::vector<std::int32_t> speciesOfInjector; ///< one entry an injector (with species)
    /// One entry an injector: its rows' species where they differ (a file's densities), row
    /// id − firstId; empty for the others, and altogether when no injector's rows differ.
    std::vector<std::vector<std::int32_t>> speciesOfRow;
    InjectorIds injectorIds; ///< with species

    bool alike() const { return species.empty(); }
    /// The species index of particle id (0 when alike). Re-injected ids, past all blocks, are of
    /// injectors that draw their particles (a file injector does not re-inject): never a row's.
    std::int32_t speciesOf(std::uint64_t id) const {
        if (alike()) return 0;
        const auto injector = static_cast<std::size_t>(injectorIds.injectorOf(id));
        const auto species = speciesOfParticles(injector);
        return species.size() == 1 ? species.front() : species[id - injectorIds.firstIds[injector]];
    }
    /// The species of injector's particles: one a row where its rows differ, else its one.
    std::span<const std::int32_t> speciesOfParticles(std::size_t injector) const {
        if (injector < speciesOfRow.size() && !speciesOfRow[injector].empty())
            return speciesOfRow[injector];
        return {&speciesOfInjector[injector], 1};
    }
    double densityOf(std::uint64_t id) const {
        return alike() ? density : species[static_cast<std::size_t>(speciesOf(id))].density;
    }
    double specificHeatOf(std::uint64_t id) const {
        return alike() ? specificHeat
                       : species[static_cast<std::size_t>(speciesOf(id))].specificHeat;
    }
    /// The heat capacity c_a m_a + c_b m_b [J/K] of particles a and b of masses m_a, m_b (as
    /// c (m_a + m_b) when alike), which a contact's dissipated energy warms alike (Eq. 2.117).
    double pairHeatCapacity(std::uint64_t a, double massA, std::uint64_t b, double massB) const {
        return alike() ? specificHeat * (massA + massB)
                       : specificHeatOf(a) * massA + specificHeatOf(b) * massB;
    }
    const MaterialSettings& materialOf(std::uint64_t id) const {
        return alike() ? material : species[static_cast<std::size_t>(speciesOf(id))].material;
    }
    /// Every species (the particles' own when alike), e.g. for the smallest response time.
    std::vector<ParticleSpecies> allSpecies() const {
        return alike()
                   ? std::vector<ParticleSpecies>{{density, material, specificHeat, susceptibility}}
                   : species;
    }
};

enum class InjectionMode { rate, allAtStart, lattice };

struct InjectionModeName {
    InjectionMode value;
    std::string_view name;
};

constexpr std::array<InjectionModeName, 3> injectionModeNames() {
    return {{{InjectionMode::rate, "rate"},
             {InjectionMode::allAtStart, "allAtStart"},
             {InjectionMode::lattice, "lattice"}}};
}

struct InjectionSettings {
    InjectionMode mode = InjectionMode::rate;
    double rate = 0;           ///< particles per second (mode rate)
    double crossSpanSpeed = 0; ///< magnitude of the random velocity ⟂ axis [m/s]
    std::uint64_t seed = 1;
    // Mode lattice: a simple cubic lattice of sites, filled in order x, y, z.
    Vec3 latticeOrigin = Vec3::Zero(); ///< lower corner of the first cell [m]
    double latticeSpacing = 0;         ///< a [m]
    std::array<int, 3> latticeSites{}; ///< per axis
    double latticeVelocitySpread = 0;  ///< uniform in [−spread, spread] per component [m/s]
    /// Each of its particles that escapes (leaves the domain box or the mesh) is replaced by a
    /// new one of its own, so the number in flight, hence the mass flow, stays constant
    /// (Section 5.2.4); models disc, cone and patch in mode rate or allAtStart.
    bool reinjectEscaped = false;
};

enum class InjectionModel { disc, cone, file, patch, ensemble };

struct InjectionModelName {
    InjectionModel value;
    std::string_view name;
};

constexpr std::array<InjectionModelName, 5> injectionModelNames() {
    return {{{InjectionModel::disc, "disc"},
             {InjectionModel::cone, "cone"},
             {InjectionModel::file, "file"},
             {InjectionModel::patch, "patch"},
             {InjectionModel::ensemble, "ensemble"}}};
}

/// A cone of directions about the injector's axis: polar angle θ between inner and outer half
/// angle, uniform over that band of the unit sphere (solid: inner 0; hollow: inner > 0).
struct ConeSettings {
    double innerHalfAngle = 0; ///< [rad]
    double outerHalfAngle = 0; ///< [rad]
    double speed = 0;          ///< mean speed along the drawn direction [m/s]
    double speedDeviation = 0; ///< standard deviation of a normal speed [m/s]; 0: fixed
};

/// Model patch (OpenFOAM's patchInjection): uniformly over the faces of a mesh patch.
struct PatchInjectionSettings {
    std::string name; ///< in constant/polyMesh/boundary
    std::optional<Vec3>
        velocity; ///< given [m/s]; none: the gas velocity's part normal to the patch
};

/// How the file of an injector of model file is read, told by its content
/// (integrate/particle_file.h).
enum class ParticleFileFormat { csv, particlesH5, foamPositions };

struct ParticleFileFormatName {
    ParticleFileFormat value;
    std::string_view name;
};

/// The formats' names in the run summary (the format is not a key: the content tells it).
constexpr std::array<ParticleFileFormatName, 3> particleFileFormatNames() {
    return {{{ParticleFileFormat::csv, "csv"},
             {ParticleFileFormat::particlesH5, "particlesH5"},
             {ParticleFileFormat::foamPositions, "foamPositions"}}};
}

/// Which particles of a previous run's particles.h5 become the rows (integrate/previous_run.h).
enum class PreviousRunSource { arrivals, frame };

struct PreviousRunSourceName {
    PreviousRunSource value;
    std::string_view name;
};

constexpr std::array<PreviousRunSourceName, 2> previousRunSourceNames() {
    return {{{PreviousRunSource::arrivals, "arrivals"}, {PreviousRunSource::frame, "frame"}}};
}

/// Model file: the file's format and what `fileCoeffs {}` says about reading it.
struct ParticleFileSettings {
    ParticleFileFormat format = ParticleFileFormat::csv;
    PreviousRunSource source = PreviousRunSource::arrivals; ///< particlesH5
    std::size_t frame = 0;        ///< particlesH5, source frame: its index in /frames
    Vec3 velocity = Vec3::Zero(); ///< foamPositions: every particle's start velocity [m/s]
};

/// One particle given by a row of a file (integrate/particle_file.h).
struct ParticleRow {
    Vec3 position = Vec3::Zero();        ///< [m]
    Vec3 velocity = Vec3::Zero();        ///< [m/s]
    double radius = 0;                   ///< [m]
    double time = 0;                     ///< injection time after the injector's start [s]
    Vec3 angularVelocity = Vec3::Zero(); ///< [rad/s], when the file gives it
    double temperature = 0;              ///< [K], when the file gives it
    double density = 0;                  ///< ρp [kg/m³], when the file gives it
};

/// One injector: where, how many, when, which sizes and with which velocity its particles
/// start. Its particles take the ids firstId … firstId + count − 1 (injector-major blocks, in
/// the order the injectors are written), so ids stay unique and deterministic.
struct InjectorSettings {
    std::string name; ///< its key in `injectors {}`; "nozzle" for the nozzle + injection form
    InjectionModel model = InjectionModel::disc;
    JetNozzle nozzle;            ///< position (centre), direction (axis), disc radius
    InjectionSettings injection; ///< mode, rate, cross-span speed, seed, lattice
    long count = 0;
    std::uint64_t firstId = 0;
    RadiusDistribution radius;
    double startTime = 0; ///< [s], the first particle's injection time
    ConeSettings cone;
    PatchInjectionSettings patch;
    ParticleFileSettings file;        ///< model file: how its file is read
    std::vector<ParticleRow> rows;    ///< model file: the particles, in order of injection time
    bool rowsGiveSpin = false;        ///< the file has wx wy wz
    bool rowsGiveTemperature = false; ///< the file has T
    bool rowsGiveDensity = false;     ///< the file has rho (a CSV) or density (a particles.h5)
    EnsembleSettings ensemble;        ///< model ensemble: the packing its rows come from
    /// What its particles are made of: the particles' own, with what the injector gives instead
    /// (with rowsGiveDensity, its first row's density).
    ParticleSpecies species;
    /// Its particles are its rows: a file's, or an ensemble's packing (at rest, at time 0).
    bool givesRows() const {
        return model == InjectionModel::file || model == InjectionModel::ensemble;
    }
};

/// The ids of injectors (their firstId and count).
InjectorIds injectorIdsOf(const std::vector<InjectorSettings>& injectors);

/// The one injector that `nozzle` + `injection` + `particles` describe.
InjectorSettings singleInjector(const InjectionSettings& injection, const JetNozzle& nozzle,
                                const ParticleSettings& particles);

} // namespace slides
