#include "slides/config/scene_reader.h"

#include "slides/analysis/physics_terms.h"
#include "slides/carrier/foam_mesh.h"
#include "slides/config/dictionary.h"
#include "slides/config/scene_keys.h"
#include "slides/core/error.h"
#include "slides/core/name_table.h"
#include "slides/integrate/ensemble.h"
#include "slides/integrate/particle_file.h"
#include "slides/integrate/previous_run.h"
#include "slides/integrate/size_distribution.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <string>
#include <type_traits>

namespace slides {

namespace {

/// Reads values by dotted path, applying the declared default, range and allowed words.
class KeyReader {
public:
    explicit KeyReader(const Dictionary& top) : top_(top) {}

    /// The line of the entry at path, 0 when it is not there.
    int lineOf(const std::string& path) const {
        std::string leaf;
        const Dictionary* parent = parentOf(path, leaf);
        return parent ? parent->lineOf(leaf) : 0;
    }

    bool has(const std::string& path) const {
        std::string leaf;
        const Dictionary* parent = parentOf(path, leaf);
        return parent && parent->has(leaf);
    }

    double scalar(const std::string& path) const {
        const double value =
            read(path, [](const Dictionary& d, const std::string& key) { return d.scalar(key); });
        checkRange(path, value);
        return value;
    }

    /// The keys of the dictionary at path, in their order (none if it is not there).
    std::vector<std::string> keysIn(const std::string& path) const {
        std::string leaf;
        const Dictionary* parent = parentOf(path, leaf);
        if (!parent || !parent->has(leaf) || !parent->isDict(leaf)) return {};
        return parent->subDict(leaf).keys();
    }

    std::optional<double> optionalScalar(const std::string& path) const {
        if (!has(path)) return std::nullopt;
        return scalar(path);
    }

    long integer(const std::string& path) const {
        const long value =
            read(path, [](const Dictionary& d, const std::string& key) { return d.integer(key); });
        checkRange(path, static_cast<double>(value));
        return value;
    }

    bool boolean(const std::string& path) const {
        return read(path,
                    [](const Dictionary& d, const std::string& key) { return d.boolean(key); });
    }

    /// A switch, or nullopt for auto.
    std::optional<bool> switchOrAuto(const std::string& path) const {
        return read(path, [](const Dictionary& d, const std::string& key) -> std::optional<bool> {
            const DictEntry* entry = d.find(key);
            if (entry && entry->items.size() == 1 && entry->items[0].isWord() &&
                entry->items[0].text() == "auto")
                return std::nullopt;
            return d.boolean(key);
        });
    }

    /// The value of a model family's key: nullopt for auto, else the model named.
    template <typename Table>
    std::optional<decltype(Table{}[0].value)> modelOrAuto(const std::string& path,
                                                          const Table& table) const {
        const std::string name = word(path);
        if (name == "auto") return std::nullopt;
        return *valueNamed(table, name);
    }

    Vec3 vector(const std::string& path) const {
        return read(
            path, [](const Dictionary& d, const std::string& key) { return Vec3(d.vector(key)); });
    }

    /// A word or a number, as written (a number printed with full precision).
    std::string wordOrNumber(const std::string& path) const {
        return read(path, [](const Dictionary& d, const std::string& key) {
            const DictEntry* entry = d.find(key);
            if (entry && entry->items.size() == 1 && entry->items[0].isNumber()) {
                char text[32];
                std::snprintf(text, sizeof text, "%.17g", entry->items[0].number());
                return std::string(text);
            }
            return d.word(key);
        });
    }

    /// Written times: `all` (nullopt) or (start end), start < end.
    std::optional<std::pair<double, double>> timeRange(const std::string& path) const {
        return read(path, [](const Dictionary& d, const std::string& key) {
            const DictEntry* entry = d.find(key);
            if (entry && entry->items.size() == 1 && entry->items[0].isWord() &&
                entry->items[0].text() == "all")
                return std::optional<std::pair<double, double>>();
            const auto values = d.scalarList(key);
            if (values.size() != 2 || !(values[0] < values[1]))
                d.fail(key, "expected all, or (start end) with start < end");
            return std::optional(std::pair(values[0], values[1]));
        });
    }

    /// A vector normalised to unit length; a zero vector is an error.
    Vec3 direction(const std::string& path) const {
        const Vec3 value = vector(path);
        if (!(value.norm() > 0)) fail(path, "a direction must not be the zero vector");
        return value.normalized();
    }

    std::array<int, 3> integerTriple(const std::string& path) const {
        const auto values = read(
            path, [](const Dictionary& d, const std::string& key) { return d.scalarList(key); });
        if (values.size() != 3)
            fail(path, "expected 3 integers, found " + std::to_string(values.size()) + " values");
        std::array<int, 3> triple{};
        for (int axis = 0; axis < 3; ++axis) {
            if (values[axis] != std::round(values[axis]) || values[axis] > 1e6)
                fail(path, "expected whole numbers of at most 1e6");
            triple[axis] = static_cast<int>(values[axis]);
            checkRange(path, triple[axis]);
        }
        return triple;
    }

    /// The word at path, which must be one of the declared allowed names.
    std::string word(const std::string& path) const {
        const std::string value =
            read(path, [](const Dictionary& d, const std::string& key) { return d.word(key); });
        checkAllowed(path, value);
        return value;
    }

    /// A list of words, each one of the declared allowed names, none twice.
    std::vector<std::string> wordList(const std::string& path) const {
        const auto values =
            read(path, [](const Dictionary& d, const std::string& key) { return d.wordList(key); });
        for (auto value = values.begin(); value != values.end(); ++value) {
            checkAllowed(path, *value);
            if (std::find(values.begin(), value, *value) != value)
                fail(path, "'" + *value + "' is listed twice");
        }
        return values;
    }

    /// Throws an InputError located at the key if present, else at its nearest parent.
    [[noreturn]] void fail(const std::string& path, const std::string& message) const {
        std::string leaf;
        const Dictionary* parent = parentOf(path, leaf);
        if (parent) parent->fail(leaf, message);
        throw InputError(top_.file(), 0, path, message);
    }

    /// A required key that the scene needs only in some configurations.
    void require(const std::string& path, const std::string& because) const {
        if (!has(path)) {
            const auto& key = declaration(path);
            fail(path, "missing key (" + key.unit + "), needed " + because + ": " + key.doc);
        }
    }

    /// Every key in the file must be declared; sub-dictionaries must be dictionaries.
    void checkKnownKeys(const Dictionary& dictionary) const {
        for (const auto& key : dictionary.keys()) {
            const std::string path = dictionary.keyPath(key);
            const KeyDeclaration* declared = findSceneKey(path);
            if (!declared && top_.isReferenced(path)) continue; // a variable of the file
            if (!declared)
                dictionary.fail(key, "unknown key; valid keys here are:" +
                                         validKeysIn(dictionary.path()));
            const bool wantsDictionary = declared->kind == KeyKind::dictionary;
            if (wantsDictionary && !dictionary.isDict(key))
                dictionary.fail(key, "expected a dictionary { ... }");
            if (!wantsDictionary && dictionary.isDict(key))
                dictionary.fail(key, "expected a value, found a dictionary");
            if (wantsDictionary) checkKnownKeys(dictionary.subDict(key));
        }
    }

private:
    template <typename Reader>
    std::invoke_result_t<Reader, const Dictionary&, const std::string&>
    read(const std::string& path, Reader reader) const {
        const KeyDeclaration& key = declaration(path);
        std::string leaf;
        if (const Dictionary* parent = parentOf(path, leaf); parent && parent->has(leaf))
            return reader(*parent, leaf);
        if (key.required()) fail(path, "missing required key (" + key.unit + "): " + key.doc);
        if (key.optional())
            throw std::logic_error("optional key read without a presence check: " + path);
        const Dictionary fallback =
            Dictionary::parseString("value " + key.fallback + ";", "default of " + path);
        return reader(fallback, "value");
    }

    const KeyDeclaration& declaration(const std::string& path) const {
        const KeyDeclaration* key = findSceneKey(path);
        if (!key) throw std::logic_error("key not in the key table: " + path);
        return *key;
    }

    void checkAllowed(const std::string& path, const std::string& value) const {
        const KeyDeclaration& key = declaration(path);
        if (key.allowed.empty() ||
            std::find(key.allowed.begin(), key.allowed.end(), value) != key.allowed.end())
            return;
        std::string valid;
        for (const auto& name : key.allowed) valid += "\n    " + name;
        fail(path, "unknown " + leafOf(path) + " '" + value + "'; valid " + leafOf(path) +
                       " names are:" + valid);
    }

    void checkRange(const std::string& path, double value) const {
        const KeyDeclaration& key = declaration(path);
        switch (key.range) {
        case KeyRange::any:
            if (!std::isfinite(value)) fail(path, "must be a finite number");
            break;
        case KeyRange::positive:
            if (!(value > 0) || !std::isfinite(value)) fail(path, "must be a positive number");
            break;
        case KeyRange::nonNegative:
            if (!(value >= 0) || !std::isfinite(value)) fail(path, "must not be negative");
            break;
        case KeyRange::atLeastOne:
            if (!(value >= 1) || !std::isfinite(value)) fail(path, "must be at least 1");
            break;
        }
        std::ostringstream bound;
        if (value < key.minimum) bound << "must be at least " << key.minimum;
        if (value > key.maximum) bound << "must be at most " << key.maximum;
        if (!bound.str().empty()) fail(path, bound.str());
    }

    /// The dictionary holding the last component of path (nullptr if a parent is missing).
    const Dictionary* parentOf(const std::string& path, std::string& leaf) const {
        const Dictionary* dictionary = &top_;
        std::size_t start = 0;
        for (std::size_t dot = path.find('.'); dot != std::string::npos;
             start = dot + 1, dot = path.find('.', start)) {
            const std::string part = path.substr(start, dot - start);
            if (!dictionary->has(part) || !dictionary->isDict(part)) return nullptr;
            dictionary = &dictionary->subDict(part);
        }
        leaf = path.substr(start);
        return dictionary;
    }

    static std::string leafOf(const std::string& path) { return path.substr(path.rfind('.') + 1); }

    static std::string validKeysIn(const std::string& dictionaryPath) {
        std::string valid;
        for (const auto& key : sceneKeys()) {
            const auto dot = key.path.rfind('.');
            const std::string parent = dot == std::string::npos ? "" : key.path.substr(0, dot);
            const std::string leaf = key.path.substr(dot + 1);
            if (keyPathMatches(parent, dictionaryPath))
                valid += "\n    " + (leaf == "*" ? std::string("<any name>") : leaf);
        }
        return valid.empty() ? " (none)" : valid;
    }

    const Dictionary& top_;
};

/// The radius distribution of the dictionary at base ("particles.radiusDistribution."); a
/// table's file is relative to caseDirectory.
RadiusDistribution readRadiusDistribution(const KeyReader& keys, const std::string& base,
                                          const std::filesystem::path& caseDirectory) {
    RadiusDistribution radius;
    radius.kind = *valueNamed(radiusDistributionNames(), keys.word(base + "type"));
    radius.minimum = keys.scalar(base + "minimum");
    radius.maximum = keys.optionalScalar(base + "maximum").value_or(INFINITY);
    if (radius.kind == RadiusDistributionKind::fixed) {
        keys.require(base + "value", "for type fixed");
        radius.value = keys.scalar(base + "value");
    } else if (radius.kind == RadiusDistributionKind::normal) {
        keys.require(base + "mean", "for type normal");
        keys.require(base + "standardDeviation", "for type normal");
        radius.mean = keys.scalar(base + "mean");
        radius.standardDeviation = keys.scalar(base + "standardDeviation");
    } else if (radius.kind == RadiusDistributionKind::table) {
        keys.require(base + "file", "for type table");
        const std::filesystem::path file = keys.word(base + "file");
        readSizeTable(file.is_absolute() ? file : caseDirectory / file, radius);
    } else if (radius.kind == RadiusDistributionKind::rosinRammler) {
        keys.require(base + "scale", "for type rosinRammler");
        keys.require(base + "spread", "for type rosinRammler");
        radius.scale = keys.scalar(base + "scale");
        radius.spread = keys.scalar(base + "spread");
    } else {
        keys.require(base + "median", "for type logNormal");
        keys.require(base + "geometricStandardDeviation", "for type logNormal");
        radius.median = keys.scalar(base + "median");
        radius.geometricStandardDeviation = keys.scalar(base + "geometricStandardDeviation");
    }
    if (!(radius.minimum < radius.maximum))
        keys.fail(base + "maximum", "must be larger than minimum");
    radius.weighting = *valueNamed(sizeWeightingNames(), keys.word(base + "weighting"));
    if (radius.weighting == SizeWeighting::mass && radius.kind == RadiusDistributionKind::normal)
        keys.fail(base + "weighting", "mass weighting is for types fixed, logNormal, "
                                      "rosinRammler and table");
    if (radius.weighting == SizeWeighting::mass &&
        radius.kind == RadiusDistributionKind::rosinRammler && !(radius.minimum > 0))
        keys.fail(base + "minimum", "a mass-weighted rosinRammler needs minimum > 0 (its number "
                                    "of particles grows without bound as r → 0)");
    const double typical = radius.meanRadius();
    if (!(typical > radius.minimum && typical < radius.maximum))
        keys.fail(base + "type", "the distribution's mean radius " + std::to_string(typical) +
                                     " m lies outside [minimum, maximum]");
    return radius;
}

/// A disc: centre, axis, radius and the cross-span direction of the dictionary at base.
JetNozzle readDisc(const KeyReader& keys, const std::string& base) {
    JetNozzle disc;
    disc.centre = keys.vector(base + ".centre");
    disc.axis = keys.direction(base + ".axis");
    disc.radius = keys.scalar(base + ".radius");
    const Vec3 crossSpan = keys.vector(base + ".crossSpanDirection");
    const Vec3 perpendicular = crossSpan - crossSpan.dot(disc.axis) * disc.axis;
    if (!(perpendicular.norm() > 1e-6 * crossSpan.norm()))
        keys.fail(base + ".crossSpanDirection", "must not be parallel to " + base + ".axis");
    disc.crossSpanDirection = perpendicular.normalized();
    return disc;
}

/// How many particles an injector of mode rate gives and how fast: two of count, rate and
/// duration.
void readRateAndCount(const KeyReader& keys, const std::string& base, InjectorSettings& injector) {
    const bool hasCount = keys.has(base + ".count");
    const long count = hasCount ? keys.integer(base + ".count") : 0;
    const auto rate = keys.optionalScalar(base + ".rate");
    const auto duration = keys.optionalScalar(base + ".duration");
    if (injector.injection.mode == InjectionMode::allAtStart) {
        keys.require(base + ".count", "for mode allAtStart");
        if (rate || duration)
            keys.fail(base + (rate ? ".rate" : ".duration"), "mode allAtStart has no rate");
        injector.count = count;
        return;
    }
    if (int(hasCount) + int(rate.has_value()) + int(duration.has_value()) != 2)
        keys.fail(base + ".count", "give two of count, rate and duration (mode rate)");
    injector.injection.rate = rate ? *rate : static_cast<double>(count) / *duration;
    const double total = hasCount ? static_cast<double>(count) : std::round(*rate * *duration);
    if (!(total >= 1 && total <= 1e15))
        keys.fail(base + ".duration",
                  "gives " + std::to_string(total) + " particles: at least 1, at most 1e15");
    injector.count = static_cast<long>(total);
}

/// The mesh patch `base.patch` names, for `what` (a patch surface or injector, asked for by the
/// key kindKey): one in the foamField carrier's constant/polyMesh/boundary, not a wedge or empty
/// patch itself; of a 3-D mesh where `needsThreeDimensions` (a surface: a wedge's or 2-D
/// mesh's patch would stand for a swept or extruded one).
FoamPatch readMeshPatch(const KeyReader& keys, const std::string& base, const std::string& kindKey,
                        const std::string& what, const Scene& scene, bool needsThreeDimensions) {
    if (scene.carrier.type != CarrierType::foamField)
        keys.fail(kindKey, what + " needs carrier type foamField (a mesh)");
    keys.require(base + ".patch", "for " + what);
    const std::string name = keys.word(base + ".patch");
    const std::vector<FoamPatch> patches = readFoamBoundary(scene.caseDirectory);
    const auto flat = [](const FoamPatch& patch) {
        return patch.type == PatchType::wedge || patch.type == PatchType::empty;
    };
    std::string names;
    for (const FoamPatch& patch : patches) {
        if (needsThreeDimensions && flat(patch))
            keys.fail(kindKey, what + " needs a 3-D mesh; patch " + patch.name +
                                   " is a wedge or empty patch");
        names += " " + patch.name;
    }
    const auto found = std::find_if(patches.begin(), patches.end(),
                                    [&](const FoamPatch& patch) { return patch.name == name; });
    if (found == patches.end())
        keys.fail(base + ".patch",
                  "no patch '" + name + "' in constant/polyMesh/boundary; patches:" + names);
    if (flat(*found))
        keys.fail(base + ".patch", "patch '" + name + "' is a wedge or empty patch, a side of " +
                                       "the axisymmetric or 2-D mesh, not a boundary of its flow");
    return *found;
}

/// An injector of model ensemble: its packing (integrate/ensemble.h) as its rows, at rest, all at
/// its start time; refused when the method cannot place them all.
void packInjector(const KeyReader& keys, const std::string& base, InjectorSettings& injector) {
    const std::string coeffs = base + ".ensembleCoeffs";
    keys.require(coeffs, "for model ensemble");
    keys.require(base + ".count", "for model ensemble");
    if (keys.has(base + ".mode") && keys.word(base + ".mode") != "allAtStart")
        keys.fail(base + ".mode", "an ensemble's particles all start at startTime");
    EnsembleSettings& ensemble = injector.ensemble;
    ensemble.method = *valueNamed(packingMethodNames(), keys.word(coeffs + ".method"));
    ensemble.growthRate = keys.scalar(coeffs + ".growthRate");
    PackingRegion& region = ensemble.region;
    region.shape = *valueNamed(packingShapeNames(), keys.word(coeffs + ".shape"));
    if (region.shape == PackingShape::box) {
        keys.require(coeffs + ".min", "for shape box");
        keys.require(coeffs + ".max", "for shape box");
        region.lower = keys.vector(coeffs + ".min");
        region.upper = keys.vector(coeffs + ".max");
        region.periodic = keys.boolean(coeffs + ".periodic");
        if (!((region.upper - region.lower).array() > 0).all())
            keys.fail(coeffs + ".max", "must exceed min in every component");
    } else {
        keys.require(coeffs + ".length", "for shape cylinder");
        region.base = injector.nozzle.centre;
        region.axis = injector.nozzle.axis;
        region.radius = injector.nozzle.radius;
        region.length = keys.scalar(coeffs + ".length");
        if (!(region.radius > 0 && region.length > 0))
            keys.fail(base + ".radius", "a cylinder needs radius > 0 and length > 0");
        if (keys.has(coeffs + ".periodic"))
            keys.fail(coeffs + ".periodic", "only a box is periodic");
    }
    const RadiusSampler sampler(injector.radius);
    std::vector<double> radii(static_cast<std::size_t>(injector.count));
    for (std::size_t k = 0; k < radii.size(); ++k)
        radii[k] = sampler.draw(injector.injection.seed, injector.firstId + k);
    PackedEnsemble packed;
    try {
        packed = packEnsemble(ensemble, radii, injector.injection.seed, injector.firstId);
    } catch (const std::length_error& tooLarge) {
        keys.fail(coeffs, std::string(tooLarge.what()));
    }
    if (!packed.complete) {
        std::ostringstream reason;
        reason << "the " << injector.count
               << " particles do not fit: " << nameOf(packingMethodNames(), ensemble.method)
               << " placed " << packed.centres.size() << " at volume fraction "
               << packed.volumeFraction(region.volume())
               << (ensemble.method == PackingMethod::randomSequentialAddition
                       ? " (random addition saturates near 0.38; lubachevskyStillinger packs "
                         "up to about 0.63)"
                       : " (jammed)");
        keys.fail(base + ".count", reason.str());
    }
    injector.rows.resize(radii.size());
    for (std::size_t k = 0; k < radii.size(); ++k) {
        injector.rows[k].position = packed.centres[k];
        injector.rows[k].radius = packed.radii[k];
    }
}

/// The fileCoeffs of an injector of model file, each key refused where the file's format
/// (integrate/particle_file.h) gives it no meaning.
void readFileCoeffs(const KeyReader& keys, const std::string& base,
                    const std::filesystem::path& file, InjectorSettings& injector) {
    const std::string coeffs = base + ".fileCoeffs";
    ParticleFileSettings& settings = injector.file;
    const auto refuseUnless = [&](bool applies, const std::string& key, const std::string& why) {
        if (!applies && keys.has(coeffs + "." + key)) keys.fail(coeffs + "." + key, why);
    };
    const bool previousRun = settings.format == ParticleFileFormat::particlesH5;
    const bool positions = settings.format == ParticleFileFormat::foamPositions;
    refuseUnless(previousRun, "source",
                 "only a previous run's particles.h5 has arrivals and frames");
    refuseUnless(positions, "velocity",
                 "only an OpenFOAM positions list takes a velocity: this file gives its own");
    if (previousRun)
        settings.source = *valueNamed(previousRunSourceNames(), keys.word(coeffs + ".source"));
    const bool frame = previousRun && settings.source == PreviousRunSource::frame;
    refuseUnless(frame, "time", "only source frame (of a particles.h5) takes a frame's time");
    if (frame) {
        keys.require(coeffs + ".time", "for source frame");
        const double time = keys.scalar(coeffs + ".time");
        const std::vector<double> times = previousRunFrameTimes(file);
        const auto index = frameAtTime(times, time);
        if (!index) {
            std::ostringstream message;
            message << "no frame of " << file.string() << " at t = " << time << " s; its "
                    << times.size() << " frames are at " << listFrameTimes(times);
            keys.fail(coeffs + ".time", message.str());
        }
        settings.frame = *index;
    }
    if (positions) {
        keys.require(coeffs + ".velocity", "for an OpenFOAM positions list (OpenFOAM's U0)");
        settings.velocity = keys.vector(coeffs + ".velocity");
    }
}

/// An injector of model file: its file's rows, and for a positions list their sizes from its
/// radiusDistribution (integrate/particle_file.h).
void readFileInjector(const KeyReader& keys, const std::string& base, const Scene& scene,
                      InjectorSettings& injector) {
    keys.require(base + ".file", "for model file");
    for (const char* given : {"count", "rate", "duration"})
        if (keys.has(base + "." + given))
            keys.fail(base + "." + given, "a file injector's particles are its rows");
    const std::filesystem::path given = keys.word(base + ".file");
    const std::filesystem::path file = given.is_absolute() ? given : scene.caseDirectory / given;
    if (!std::filesystem::is_regular_file(file))
        keys.fail(base + ".file", "no file " + file.string());
    injector.file.format = particleFileFormat(file);
    const std::string sizes = base + ".radiusDistribution";
    if (injector.file.format == ParticleFileFormat::foamPositions)
        injector.radius = keys.has(sizes)
                              ? readRadiusDistribution(keys, sizes + ".", scene.caseDirectory)
                              : scene.particles.radius;
    else if (keys.has(sizes))
        keys.fail(sizes, "this file gives the particles' sizes (only an OpenFOAM positions list "
                         "takes a radiusDistribution)");
    readFileCoeffs(keys, base, file, injector);
    readParticleFile(file, injector);
    injector.count = static_cast<long>(injector.rows.size());
}

/// The injectors of `injectors {}`, their ids in blocks in the order written.
std::vector<InjectorSettings> readInjectors(const KeyReader& keys, const Dictionary& top,
                                            const Scene& scene) {
    for (const char* shorthand :
         {"mode", "rate", "crossSpanSpeed", "latticeCoeffs", "reinjectEscaped"})
        if (keys.has(std::string("injection.") + shorthand))
            keys.fail(std::string("injection.") + shorthand,
                      "with injectors, injection gives only the seed");
    if (keys.has("particles.count"))
        keys.fail("particles.count", "with injectors, their counts give the number of particles");
    const Dictionary& list = top.subDict("injectors");
    if (list.keys().empty()) keys.fail("injectors", "no injector listed");
    std::vector<InjectorSettings> injectors;
    std::uint64_t firstId = 0;
    for (const auto& name : list.keys()) {
        const std::string base = "injectors." + name;
        InjectorSettings injector;
        injector.name = name;
        injector.model = *valueNamed(injectionModelNames(), keys.word(base + ".model"));
        injector.firstId = firstId;
        injector.startTime = keys.scalar(base + ".startTime");
        injector.injection.seed = scene.injection.seed;
        injector.nozzle = readDisc(keys, base);
        if (injector.model == InjectionModel::file) {
            readFileInjector(keys, base, scene, injector);
        } else if (injector.model == InjectionModel::ensemble) {
            injector.injection.mode = InjectionMode::allAtStart;
            injector.count = keys.integer(base + ".count");
            injector.radius = keys.has(base + ".radiusDistribution")
                                  ? readRadiusDistribution(keys, base + ".radiusDistribution.",
                                                           scene.caseDirectory)
                                  : scene.particles.radius;
            packInjector(keys, base, injector);
        } else {
            injector.injection.mode = *valueNamed(injectionModeNames(), keys.word(base + ".mode"));
            readRateAndCount(keys, base, injector);
            injector.radius = keys.has(base + ".radiusDistribution")
                                  ? readRadiusDistribution(keys, base + ".radiusDistribution.",
                                                           scene.caseDirectory)
                                  : scene.particles.radius;
        }
        if (injector.model == InjectionModel::disc) {
            injector.injection.crossSpanSpeed = keys.scalar(base + ".crossSpanSpeed");
        } else if (keys.has(base + ".crossSpanSpeed")) {
            keys.fail(base + ".crossSpanSpeed", "only model disc adds a cross-span speed");
        }
        if (injector.model == InjectionModel::patch) {
            const std::string coeffs = base + ".patchCoeffs";
            keys.require(coeffs, "for model patch");
            injector.patch.name =
                readMeshPatch(keys, coeffs, base + ".model", "a patch injector", scene, false).name;
            if (keys.has(coeffs + ".velocity"))
                injector.patch.velocity = keys.vector(coeffs + ".velocity");
        } else if (keys.has(base + ".patchCoeffs")) {
            keys.fail(base + ".patchCoeffs", "only model patch takes patchCoeffs");
        }
        if (injector.model == InjectionModel::cone) {
            const std::string cone = base + ".coneCoeffs";
            keys.require(cone, "for model cone");
            constexpr double radiansPerDegree = std::numbers::pi / 180;
            injector.cone.innerHalfAngle = radiansPerDegree * keys.scalar(cone + ".innerHalfAngle");
            injector.cone.outerHalfAngle = radiansPerDegree * keys.scalar(cone + ".outerHalfAngle");
            injector.cone.speed = keys.scalar(cone + ".speed");
            injector.cone.speedDeviation = keys.scalar(cone + ".speedStandardDeviation");
            if (!(injector.cone.outerHalfAngle > injector.cone.innerHalfAngle))
                keys.fail(cone + ".outerHalfAngle", "must be larger than innerHalfAngle");
        } else if (keys.has(base + ".coneCoeffs")) {
            keys.fail(base + ".coneCoeffs", "only model cone takes coneCoeffs");
        }
        injector.injection.reinjectEscaped = keys.boolean(base + ".reinjectEscaped");
        if (injector.injection.reinjectEscaped && injector.givesRows())
            keys.fail(base + ".reinjectEscaped",
                      "a file's or an ensemble's particles are its rows: none to draw anew");
        if (injector.model != InjectionModel::file && keys.has(base + ".fileCoeffs"))
            keys.fail(base + ".fileCoeffs", "only model file takes fileCoeffs");
        if (injector.model != InjectionModel::ensemble && keys.has(base + ".ensembleCoeffs"))
            keys.fail(base + ".ensembleCoeffs", "only model ensemble takes ensembleCoeffs");
        firstId += static_cast<std::uint64_t>(injector.count);
        injectors.push_back(std::move(injector));
    }
    return injectors;
}

/// A file's spins and temperatures need the particles to keep them: never dropped silently.
void requireFileStatesKept(const KeyReader& keys, const Scene& scene) {
    for (const InjectorSettings& injector : scene.injectors) {
        // A frame's spins and temperatures are taken where the run keeps them (previous_run.h).
        if (injector.file.source == PreviousRunSource::frame) continue;
        const std::string key = "injectors." + injector.name + ".file";
        if (injector.rowsGiveSpin && !tracksSpin(scene))
            keys.fail(key, "gives spins (wx wy wz), but the particles keep none: set physics.spin "
                           "on, collisions.model, or a surface that rebounds or deposits");
        if (injector.rowsGiveTemperature && scene.physics.heatTransfer == HeatTransferModel::none)
            keys.fail(key, "gives temperatures (T), but heat transfer is off: set "
                           "physics.heatTransfer.model (not auto)");
    }
}

MaterialSettings readMaterial(const KeyReader& keys, const std::string& base) {
    MaterialSettings material;
    material.bulkModulus = keys.optionalScalar(base + ".bulkModulus").value_or(0);
    material.shearModulus = keys.optionalScalar(base + ".shearModulus").value_or(0);
    material.yieldStress = keys.optionalScalar(base + ".yieldStress").value_or(0);
    material.surfaceEnergy = keys.optionalScalar(base + ".surfaceEnergy").value_or(0);
    return material;
}

/// The particle species of the injectors (`injectors.NAME.density`, `.material {}`,
/// `.specificHeat`, `.susceptibility`, each defaulting to the particles' own; a file's
/// densities per row, integrate/particle_file.h); every model takes each particle's own.
/// Injectors all alike leave the particles one species, theirs.
void readSpecies(const KeyReader& keys, Scene& scene) {
    ParticleSettings& particles = scene.particles;
    const ElectromagneticSettings& fields = scene.physics.electromagnetic;
    const std::string susceptibility = "physics.electromagnetic.magnetisation.susceptibility";
    particles.susceptibility = keys.scalar(susceptibility);
    if (keys.has(susceptibility) && !fields.magnetisable())
        keys.fail(susceptibility, "acts with physics.electromagnetic.magnetisation.model linear");
    if (!(particles.susceptibility > -1))
        keys.fail(susceptibility, "must be above −1 (µr = 1 + χm > 0)");
    if (scene.injectors.empty()) return;
    const ParticleSpecies own{particles.density, particles.material, particles.specificHeat,
                              particles.susceptibility};
    std::vector<ParticleSpecies> species;
    std::vector<std::int32_t> ofInjector;
    std::vector<std::vector<std::int32_t>> ofRow;
    const auto indexOf = [&](const ParticleSpecies& one) {
        auto found = std::find(species.begin(), species.end(), one);
        if (found == species.end()) found = species.insert(species.end(), one);
        return static_cast<std::int32_t>(found - species.begin());
    };
    for (InjectorSettings& injector : scene.injectors) {
        const std::string base = "injectors." + injector.name;
        if (injector.rowsGiveDensity && keys.has(base + ".density"))
            keys.fail(base + ".density", "its file gives its particles' densities (" +
                                             keys.word(base + ".file") + ")");
        ParticleSpecies mine = own;
        mine.density = keys.optionalScalar(base + ".density").value_or(own.density);
        const MaterialSettings given = readMaterial(keys, base + ".material");
        for (auto member : {&MaterialSettings::bulkModulus, &MaterialSettings::shearModulus,
                            &MaterialSettings::yieldStress, &MaterialSettings::surfaceEnergy})
            if (given.*member > 0) mine.material.*member = given.*member;
        mine.specificHeat = keys.optionalScalar(base + ".specificHeat").value_or(own.specificHeat);
        if (keys.has(base + ".susceptibility") && !fields.magnetisable())
            keys.fail(base + ".susceptibility",
                      "acts with physics.electromagnetic.magnetisation.model linear");
        mine.susceptibility =
            keys.optionalScalar(base + ".susceptibility").value_or(own.susceptibility);
        if (!(mine.susceptibility > -1))
            keys.fail(base + ".susceptibility", "must be above −1 (µr = 1 + χm > 0)");
        std::vector<std::int32_t> rows;
        if (injector.rowsGiveDensity) {
            for (const ParticleRow& row : injector.rows) {
                ParticleSpecies its = mine;
                its.density = row.density;
                rows.push_back(indexOf(its));
            }
            mine.density = injector.rows.front().density;
        }
        injector.species = mine;
        ofInjector.push_back(indexOf(mine));
        if (std::all_of(rows.begin(), rows.end(), [&](auto s) { return s == rows.front(); }))
            rows.clear(); // one species: the injector's
        ofRow.push_back(std::move(rows));
    }
    particles.density = species.front().density;
    particles.material = species.front().material;
    particles.specificHeat = species.front().specificHeat;
    particles.susceptibility = species.front().susceptibility;
    if (species.size() == 1) return; // alike: the particles' values are the injectors'
    particles.species = std::move(species);
    particles.speciesOfInjector = std::move(ofInjector);
    if (std::any_of(ofRow.begin(), ofRow.end(), [](const auto& rows) { return !rows.empty(); }))
        particles.speciesOfRow = std::move(ofRow);
    particles.injectorIds = injectorIdsOf(scene.injectors);
}

/// The porous layer of an erode surface (Section 5.2): a plane whose material gives the moduli.
ErosionSettings readErosion(const KeyReader& keys, const std::string& base,
                            const Surface& surface) {
    const std::string layer = base + ".erosion";
    if (!surface.patch.empty()) keys.fail(base + ".interaction", "erode needs a plane surface");
    keys.require(layer, "by interaction erode");
    keys.require(base + ".material.bulkModulus", "by interaction erode (the layer's matrix)");
    keys.require(base + ".material.shearModulus", "by interaction erode (the layer's matrix)");
    keys.require(layer + ".thickness", "by interaction erode");
    keys.require(layer + ".width", "by interaction erode");
    keys.require(layer + ".threshold", "by interaction erode (σ0 of Eq. 5.6)");
    ErosionSettings erosion;
    erosion.thickness = keys.scalar(layer + ".thickness");
    erosion.width = keys.scalar(layer + ".width");
    erosion.porosity = keys.scalar(layer + ".porosity");
    erosion.boundWeight = keys.scalar(layer + ".boundWeight");
    erosion.threshold = keys.scalar(layer + ".threshold");
    erosion.cells = keys.integerTriple(layer + ".cells");
    if (erosion.cells[0] % 2 != 0 || erosion.cells[1] % 2 != 0)
        keys.fail(layer + ".cells", "the cells across the width must be even (a grid line on "
                                    "the layer's centre, where the stress history is taken)");
    return erosion;
}

std::optional<JetTurbulence> readJetTurbulence(const KeyReader& keys) {
    const std::string base = "carrier.turbulence.";
    if (!keys.has("carrier.turbulence")) return std::nullopt;
    JetTurbulence turbulence;
    turbulence.intensity = keys.scalar(base + "intensity");
    turbulence.scaling = *valueNamed(turbulenceScalingNames(), keys.word(base + "scaling"));
    if (turbulence.scaling == TurbulenceScaling::uniform) {
        keys.require(base + "lengthScale", "for scaling uniform");
        turbulence.lengthScale = keys.scalar(base + "lengthScale");
    } else {
        keys.require(base + "lengthScaleToHalfWidth", "for scaling jetLocal");
        turbulence.lengthScaleToHalfWidth = keys.scalar(base + "lengthScaleToHalfWidth");
    }
    return turbulence;
}

/// The pulsed nozzle of an analytic jet (carrier/pulsed_jet.h) in coeffs, or nullopt for a steady
/// one (no pulsation {}, or amplitude 0).
std::optional<JetPulsation> readJetPulsation(const KeyReader& keys, const std::string& coeffs) {
    const std::string base = coeffs + ".pulsation";
    if (!keys.has(base)) return std::nullopt;
    JetPulsation pulsation;
    pulsation.amplitude = keys.scalar(base + ".amplitude");
    if (!(pulsation.amplitude < 1))
        keys.fail(base + ".amplitude",
                  "must be below 1: at 1 or more the nozzle velocity U0 (1 + A sin 2πft) would "
                  "stop or reverse");
    if (keys.has(base + ".frequency")) pulsation.frequency = keys.scalar(base + ".frequency");
    if (pulsation.amplitude == 0) return std::nullopt;
    keys.require(base + ".frequency", "by amplitude > 0");
    return pulsation;
}

/// The unsteady forces and spin of physics, as given or left to the scene analysis (auto).
void readUnsteadyForces(const KeyReader& keys, Scene& scene) {
    PhysicsSettings& physics = scene.physics;
    auto& automatic = physics.automaticTerms;
    const auto history = keys.modelOrAuto("physics.history.model", historyModelNames());
    physics.history = history.value_or(HistoryModel::none);
    if (!history) automatic.push_back({PhysicsTerm::history, ""});
    physics.historyAccuracy = keys.scalar("physics.history.accuracy");
    if (physics.historyAccuracy >= 1)
        keys.fail("physics.history.accuracy", "must be below 1 (a relative error)");
    const auto addedMass = keys.switchOrAuto("physics.addedMass");
    physics.addedMass = addedMass.value_or(false);
    if (!addedMass) automatic.push_back({PhysicsTerm::addedMass, ""});
    const auto pressureGradient = keys.switchOrAuto("physics.pressureGradient");
    physics.pressureGradient = pressureGradient.value_or(false);
    if (!pressureGradient) automatic.push_back({PhysicsTerm::pressureGradient, ""});

    const auto spin = keys.switchOrAuto("physics.spin");
    const auto lift = keys.modelOrAuto("physics.lift", liftModelNames());
    physics.lift = lift.value_or(LiftModel::none);
    if (!lift) {
        automatic.push_back({PhysicsTerm::shearLift, ""});
        automatic.push_back({PhysicsTerm::spinLift, spin == false ? "needs physics.spin" : ""});
    }
    if (usesSpinLift(physics.lift) && spin == false)
        keys.fail("physics.lift", "magnus lift needs the particle spin: set physics.spin on");
    physics.spinHistory = keys.boolean("physics.spinHistory");
    if (physics.spinHistory && spin == false)
        keys.fail("physics.spinHistory", "the spin's history needs the spin: set physics.spin on");
    // Spin matters to Magnus lift and to its own history: auto follows them (given, or as the
    // analysis decides for Magnus lift).
    physics.spin = spin.value_or(usesSpinLift(physics.lift) || physics.spinHistory);
    if (!spin && !lift && !physics.spinHistory) automatic.push_back({PhysicsTerm::spin, ""});
    physics.faxen = keys.boolean("physics.faxen");
    if (physics.faxen && !givesVelocityLaplacian(scene.carrier.type))
        keys.fail("physics.faxen",
                  "the Faxén terms need ∇²U of the carrier, which planePoiseuille, "
                  "taylorGreenVortex and oscillatingGas give in closed form; foamField's cellPoint "
                  "field is linear in each tetrahedron (∇²U = 0 there) and the jets' is not "
                  "derived: set it off");
}

/// The unsteady forces left to auto made unavailable: a step other than the Maxey–Riley one
/// takes the scene's particles.
void leaveUnsteadyForcesOff(PhysicsSettings& physics, const std::string& because) {
    constexpr std::array unsteady{PhysicsTerm::history,          PhysicsTerm::addedMass,
                                  PhysicsTerm::pressureGradient, PhysicsTerm::shearLift,
                                  PhysicsTerm::spinLift,         PhysicsTerm::spin};
    for (AutomaticTerm& automatic : physics.automaticTerms)
        if (automatic.unavailable.empty() &&
            std::find(unsteady.begin(), unsteady.end(), automatic.term) != unsteady.end())
            automatic.unavailable = because;
}

/// physics.electromagnetic.coils and .magnetisation.
void readCoilsAndMagnetisation(const KeyReader& keys, ElectromagneticSettings& fields) {
    const std::string base = "physics.electromagnetic.";
    for (const std::string& name : keys.keysIn(base + "coils")) {
        const std::string coil = base + "coils." + name;
        fields.coils.push_back({name, keys.vector(coil + ".centre"), keys.direction(coil + ".axis"),
                                keys.scalar(coil + ".radius"), keys.scalar(coil + ".current")});
    }
    fields.magnetisation =
        *valueNamed(magnetisationModelNames(), keys.word(base + "magnetisation.model"));
    if (fields.magnetisable() && fields.uniform())
        keys.fail(base + "magnetisation.model",
                  "a uniform B pulls no magnetisable particle (Eq. 2.110): give the field's "
                  "gradient by physics.electromagnetic.coils");
    const bool needsLorentzStep = !fields.uniform() || fields.magnetisable();
    if (needsLorentzStep && !fields.on())
        keys.fail(base + (fields.magnetisable() ? "magnetisation.model" : "coils"),
                  "the fields act through physics.electromagnetic.model lorentz (the charge may "
                  "be zero)");
}

/// physics.electromagnetic; its exact flow replaces the Maxey–Riley step's, so the unsteady
/// forces stay off (an `auto` one among them is left unavailable).
void readElectromagnetic(const KeyReader& keys, PhysicsSettings& physics, std::uint64_t seed) {
    ElectromagneticSettings& fields = physics.electromagnetic;
    const std::string base = "physics.electromagnetic.";
    fields.model = *valueNamed(electromagneticModelNames(), keys.word(base + "model"));
    fields.electricField = keys.vector(base + "E");
    fields.magneticField = keys.vector(base + "B");
    fields.charge = *valueNamed(chargeModelNames(), keys.word(base + "charge.model"));
    fields.chargeValue = keys.scalar(base + "charge.value");
    fields.oppositeSignFraction = keys.scalar(base + "charge.oppositeSignFraction");
    if (!(fields.oppositeSignFraction >= 0 && fields.oppositeSignFraction <= 1))
        keys.fail(base + "charge.oppositeSignFraction", "must lie in [0, 1] (a fraction of the "
                                                        "particles)");
    fields.seed = seed;
    fields.coulomb.model = *valueNamed(coulombModelNames(), keys.word(base + "coulomb.model"));
    fields.coulomb.cutoff = keys.scalar(base + "coulomb.cutoff");
    fields.coulomb.permittivity = keys.scalar(base + "coulomb.permittivity");
    readCoilsAndMagnetisation(keys, fields);
    // The particles carry their charges with the Lorentz step (integrate/charged_motion.h).
    if (fields.coulomb.on() && !fields.on())
        keys.fail(base + "coulomb.model", "Coulomb forces act between charged particles, which "
                                          "physics.electromagnetic.model lorentz gives (E and B "
                                          "may be zero)");
    if (!fields.on()) return;
    if (physics.unsteadyForces())
        keys.fail(base + "model", "the Lorentz step does not take the unsteady forces (history, "
                                  "added mass, pressure gradient, lift, spin, Faxén): set them "
                                  "off");
    leaveUnsteadyForcesOff(physics, "not with physics.electromagnetic");
}

/// physics.dispersion and physics.heatTransfer with what they need from the other sections.
void readDispersionAndHeat(const KeyReader& keys, Scene& scene) {
    PhysicsSettings& physics = scene.physics;
    const auto dispersion = keys.modelOrAuto("physics.dispersion.model", dispersionModelNames());
    physics.dispersion = dispersion.value_or(DispersionModel::none);
    const bool laminarJet =
        scene.carrier.type != CarrierType::foamField && !scene.carrier.turbulence;
    if (!dispersion)
        physics.automaticTerms.push_back(
            {PhysicsTerm::dispersion, laminarJet ? "needs carrier.turbulence (k, ε)" : ""});
    physics.dispersionConstants.Cmu = keys.scalar("physics.dispersion.Cmu");
    physics.dispersionConstants.turbulentSchmidtNumber =
        keys.scalar("physics.dispersion.turbulentSchmidtNumber");
    // An OpenFOAM carrier brings its own k and ε fields; an analytic jet needs them described.
    if (physics.dispersion != DispersionModel::none && scene.carrier.type != CarrierType::foamField)
        keys.require("carrier.turbulence", "by physics.dispersion (k and ε of an analytic jet)");
    const auto heat = keys.modelOrAuto("physics.heatTransfer.model", heatTransferModelNames());
    physics.heatTransfer = heat.value_or(HeatTransferModel::none);
    if (!heat)
        physics.automaticTerms.push_back(
            {PhysicsTerm::heatTransfer,
             keys.has("particles.specificHeat") ? "" : "needs particles.specificHeat"});
    scene.particles.thermalConductivity =
        keys.optionalScalar("particles.thermalConductivity").value_or(0);
    scene.fluid.thermalConductivity = keys.scalar("fluid.thermalConductivity");
    scene.fluid.specificHeat = keys.scalar("fluid.specificHeat");
    scene.particles.injectionTemperature =
        keys.optionalScalar("particles.injectionTemperature").value_or(scene.fluid.temperature);
    if (physics.heatTransfer != HeatTransferModel::none)
        keys.require("particles.specificHeat", "by physics.heatTransfer");
    scene.particles.specificHeat = keys.optionalScalar("particles.specificHeat").value_or(0);
}

/// collisions and deposition, and what their laws need of the particles' and surfaces'
/// materials (after the surfaces are read).
void readCollisionsAndDeposition(const KeyReader& keys, Scene& scene) {
    CollisionSettings& collisions = scene.collisions;
    const auto model = keys.modelOrAuto("collisions.model", collisionModelNames());
    collisions.model = model.value_or(CollisionModel::none);
    RestitutionSettings& restitution = collisions.restitution;
    restitution.model =
        *valueNamed(restitutionModelNames(), keys.word("collisions.restitution.model"));
    restitution.coefficient = keys.scalar("collisions.restitution.coefficient");
    if (restitution.coefficient > 1)
        keys.fail("collisions.restitution.coefficient", "must not exceed 1");
    restitution.yieldPressureFactor = keys.scalar("collisions.restitution.yieldPressureFactor");
    collisions.friction.staticCoefficient = keys.scalar("collisions.friction.static");
    collisions.friction.dynamicCoefficient = keys.scalar("collisions.friction.dynamic");
    collisions.heating = keys.boolean("collisions.heating");
    ContactConductionSettings& conduction = collisions.conduction;
    conduction.model = *valueNamed(contactConductionNames(), keys.word("collisions.conduction"));
    if (conduction.model != ContactConduction::none) {
        if (collisions.model != CollisionModel::softSphere)
            keys.fail("collisions.conduction",
                      "needs collisions.model softSphere, whose contacts last");
        keys.require("particles.thermalConductivity", "by collisions.conduction");
        conduction.particleConductivity = scene.particles.thermalConductivity;
        conduction.gasConductivity = scene.fluid.thermalConductivity;
    }
    if (collisions.model == CollisionModel::softSphere) {
        // The damped Hertz impact restitutes one e whatever the speed (physics/soft_contact.h).
        if (keys.has("collisions.restitution.model") &&
            restitution.model != RestitutionModel::constant)
            keys.fail("collisions.restitution.model",
                      "must be constant for collisions.model softSphere, whose damping restitutes "
                      "one coefficient at every impact speed");
        restitution.model = RestitutionModel::constant;
        if (!(restitution.coefficient > 0))
            keys.fail("collisions.restitution.coefficient",
                      "must be positive for collisions.model softSphere");
        collisions.softSphere.damping =
            *valueNamed(softSphereDampingNames(), keys.word("collisions.softSphereCoeffs.damping"));
        collisions.softSphere.neighbourSkin =
            keys.scalar("collisions.softSphereCoeffs.neighbourSkin");
        SoftSphereSettings& softSphere = collisions.softSphere;
        softSphere.contactLaw = *valueNamed(normalContactLawNames(),
                                            keys.word("collisions.softSphereCoeffs.contactLaw"));
        if (softSphere.contactLaw == NormalContactLaw::linearSpringDashpot ||
            softSphere.contactLaw == NormalContactLaw::waltonBraun) {
            keys.require("collisions.softSphereCoeffs.normalStiffness",
                         "by collisions.softSphereCoeffs.contactLaw");
            softSphere.normalStiffness = keys.scalar("collisions.softSphereCoeffs.normalStiffness");
        }
        if (softSphere.contactLaw == NormalContactLaw::viscoelasticHertz) {
            keys.require("collisions.softSphereCoeffs.dissipativeTime",
                         "by collisions.softSphereCoeffs.contactLaw viscoelasticHertz");
            softSphere.dissipativeTime = keys.scalar("collisions.softSphereCoeffs.dissipativeTime");
        }
        collisions.friction.regularisation = *valueNamed(
            frictionRegularisationNames(), keys.word("collisions.friction.regularisation"));
        collisions.friction.regularisationSpeed = keys.scalar("collisions.friction.slipSpeed");
    }

    AdhesionSettings& adhesion = scene.deposition;
    adhesion.model = *valueNamed(adhesionModelNames(), keys.word("deposition.adhesion"));
    adhesion.factor = keys.scalar("deposition.adhesionFactor");
    adhesion.contactSeparation = keys.scalar("deposition.contactSeparation");
    if (adhesion.model == AdhesionModel::hamaker) {
        keys.require("deposition.hamakerConstant", "by deposition.adhesion hamaker");
        adhesion.hamakerConstant = keys.scalar("deposition.hamakerConstant");
    }

    // The materials each law reads (physics/contact_pair.h, restitution.h, adhesion.h).
    const bool velocityDependent = restitution.model == RestitutionModel::velocityDependent;
    if (!model) { // auto: impulses need what requireMaterial below asks of the particles
        std::string unavailable;
        for (const char* property : {"bulkModulus", "shearModulus", "yieldStress"})
            if (velocityDependent && unavailable.empty() &&
                !keys.has(std::string("particles.material.") + property))
                unavailable = std::string("needs particles.material.") + property;
        scene.physics.automaticTerms.push_back({PhysicsTerm::collisions, unavailable});
    }
    // Hertz forces (softSphere) and the velocity-dependent restitution read the moduli.
    const bool softSphere = collisions.model == CollisionModel::softSphere;
    const std::string moduliReader =
        softSphere ? " (collisions.model softSphere)" : " (restitution velocityDependent)";
    const auto requireMaterial = [&](const std::string& base, bool needsYield,
                                     const std::string& because) {
        if (velocityDependent || softSphere) {
            keys.require(base + ".bulkModulus", because + moduliReader);
            keys.require(base + ".shearModulus", because + moduliReader);
        }
        if (needsYield) keys.require(base + ".yieldStress", because);
    };
    bool anyContact = collisions.model != CollisionModel::none;
    bool anyDeposit = false;
    for (const Surface& surface : scene.surfaces) {
        const std::string base = "surfaces." + surface.name;
        if (surface.interaction == SurfaceInteraction::absorb) continue;
        anyContact = true;
        requireMaterial(base + ".material", false, "by interaction of surface " + surface.name);
        if (surface.interaction != SurfaceInteraction::deposit) continue;
        anyDeposit = true;
        if (adhesion.model != AdhesionModel::hamaker) // the work of adhesion W₁₂
            keys.require(base + ".material.surfaceEnergy",
                         "by deposition.adhesion " + keys.word("deposition.adhesion"));
    }
    if (anyContact)
        requireMaterial("particles.material", velocityDependent,
                        "by collisions or a surface's interaction");
    if (anyDeposit) {
        // Eq. 5.9's compression time δt₁ (Eq. 2.64) needs the moduli and yield stress.
        requireMaterial("particles.material", true, "by a deposit surface (Eq. 5.9)");
        if (!velocityDependent) {
            keys.require("particles.material.bulkModulus", "by a deposit surface (Eq. 5.9)");
            keys.require("particles.material.shearModulus", "by a deposit surface (Eq. 5.9)");
        }
        if (adhesion.model != AdhesionModel::hamaker)
            keys.require("particles.material.surfaceEnergy",
                         "by deposition.adhesion " + keys.word("deposition.adhesion"));
    }
}

/// Without a gas, every term but collisions is off: one switched on is an error, and auto
/// stays off (the analysis has no gas to trace).
void refuseGasTerms(const KeyReader& keys, Scene& scene) {
    for (const PhysicsTermName& row : physicsTermNames()) {
        if (row.value == PhysicsTerm::collisions) continue;
        if (termIsOn(scene, row.value))
            keys.fail(std::string(row.key), "needs a carrier gas, and carrier.type is none");
    }
    for (AutomaticTerm& automatic : scene.physics.automaticTerms)
        if (automatic.term != PhysicsTerm::collisions && automatic.unavailable.empty())
            automatic.unavailable = "needs a carrier gas";
}

/// The mesh patch a surface of type patch is: one of type wall or patch, not a symmetry plane.
std::string readPatchName(const KeyReader& keys, const std::string& base, const Scene& scene) {
    if (keys.has(base + ".point") || keys.has(base + ".normal"))
        keys.fail(base + ".type", "a patch surface takes its shape from the mesh: no point or "
                                  "normal");
    const FoamPatch patch =
        readMeshPatch(keys, base, base + ".type", "a patch surface", scene, true);
    if (patch.type == PatchType::symmetry)
        keys.fail(base + ".patch", "patch '" + patch.name + "' is a symmetry plane, not a wall");
    return patch.name;
}

CarrierSettings readCarrier(const KeyReader& keys, const FluidSettings& fluid) {
    CarrierSettings carrier;
    const std::string type = keys.word("carrier.type");
    carrier.type = *valueNamed(carrierTypeNames(), type);
    if (carrier.type == CarrierType::none) return carrier;
    const std::string coeffs = "carrier." + type + "Coeffs";
    if (carrier.type != CarrierType::foamField) keys.require(coeffs, "for carrier type " + type);
    if (carrier.type == CarrierType::foamField) {
        carrier.foamTime = keys.wordOrNumber(coeffs + ".time");
        carrier.interpolation =
            *valueNamed(foamInterpolationNames(), keys.word(coeffs + ".interpolation"));
        carrier.latticeSpacing = keys.scalar(coeffs + ".latticeSpacing");
        if (keys.has(coeffs + ".times"))
            carrier.foamSeries = FoamSeriesSettings{keys.timeRange(coeffs + ".times"),
                                                    keys.optionalScalar(coeffs + ".cycle"),
                                                    keys.boolean(coeffs + ".readAhead")};
        else
            for (const char* key : {".cycle", ".readAhead"})
                if (keys.has(coeffs + key))
                    keys.fail(coeffs + key, "it concerns a time series: give times too");
        return carrier;
    }
    carrier.viscosity = fluid.kinematicViscosity;
    if (carrier.type == CarrierType::oscillatingGas) {
        carrier.oscillationAmplitude = keys.vector(coeffs + ".amplitude");
        carrier.oscillationFrequency = keys.scalar(coeffs + ".frequency");
        return carrier;
    }
    if (carrier.type == CarrierType::taylorGreenVortex) {
        carrier.vortexVelocity = keys.scalar(coeffs + ".velocity");
        carrier.vortexWavelength = keys.scalar(coeffs + ".wavelength");
        return carrier;
    }
    if (carrier.type == CarrierType::planePoiseuille) {
        carrier.centrelineVelocity = keys.scalar(coeffs + ".centrelineVelocity");
        carrier.channelHalfWidth = keys.scalar(coeffs + ".halfWidth");
        return carrier;
    }
    carrier.nozzleVelocity = keys.scalar(coeffs + ".nozzleVelocity");
    carrier.coreLength = keys.scalar(coeffs + ".coreLength");
    carrier.viscosity =
        keys.optionalScalar(coeffs + ".effectiveViscosity").value_or(fluid.kinematicViscosity);
    carrier.turbulence = readJetTurbulence(keys);
    carrier.pulsation = readJetPulsation(keys, coeffs);
    if (carrier.type == CarrierType::analyticJet) {
        carrier.profile = *valueNamed(jetGeometryNames(), keys.word(coeffs + ".profile"));
        carrier.C1 = keys.optionalScalar(coeffs + ".C1");
        carrier.C2 = keys.optionalScalar(coeffs + ".C2");
        carrier.C3 = keys.optionalScalar(coeffs + ".C3");
        if (carrier.C1.has_value() != carrier.C3.has_value())
            keys.fail(coeffs + (carrier.C1 ? ".C1" : ".C3"), "give C1 and C3 together");
        if (carrier.C2 && !carrier.C1)
            keys.fail(coeffs + ".C2", "C2 follows from C1 and C3; give those too");
        if (carrier.C2 &&
            std::abs(*carrier.C2 - *carrier.C1 / (3 * *carrier.C3)) > 1e-9 * std::abs(*carrier.C2))
            keys.fail(coeffs + ".C2", "continuity of Eq. 5.10/5.11 requires C2 = C1/(3 C3) = " +
                                          std::to_string(*carrier.C1 / (3 * *carrier.C3)));
    }
    return carrier;
}

/// planePoiseuille: the parabola U(1 − y²/h²) keeps growing past the walls; over the domain it
/// must stay within the bound of the centreline velocity's key, or a particle straying there
/// meets a gas no jet has (h = 1e-300 gave an infinite velocity).
void requireBoundedChannelFlow(const KeyReader& keys, const Scene& scene) {
    const CarrierSettings& carrier = scene.carrier;
    const double edge = std::max(std::abs(scene.domain.min.y()), std::abs(scene.domain.max.y()));
    const double widths = edge / carrier.channelHalfWidth;
    const double fastest = carrier.centrelineVelocity * std::max(1.0, widths * widths - 1);
    const double bound = findSceneKey("carrier.planePoiseuilleCoeffs.centrelineVelocity")->maximum;
    if (fastest <= bound) return;
    std::ostringstream reason;
    reason << "the gas speed U|1 − y²/h²| reaches " << fastest << " m/s at the domain's y = ±"
           << edge << " m, more than " << bound << " m/s: widen the channel or narrow the domain";
    keys.fail("carrier.planePoiseuilleCoeffs.halfWidth", reason.str());
}

/// The escape box, and the nozzle inside it.
void readDomain(const KeyReader& keys, Scene& scene) {
    scene.domain.min = keys.vector("domain.min");
    scene.domain.max = keys.vector("domain.max");
    if (!(scene.domain.min.array() < scene.domain.max.array()).all())
        keys.fail("domain.max", "must exceed domain.min in every component");
    if (!scene.injectors.empty() && !keys.has("nozzle")) return; // each injector is checked
    const Vec3& nozzle = scene.nozzle.centre;
    if (!((nozzle.array() > scene.domain.min.array()).all() &&
          (nozzle.array() < scene.domain.max.array()).all()))
        keys.fail("nozzle.centre", "lies outside the domain box");
}

} // namespace

Scene sceneFromDictionary(const Dictionary& dictionary,
                          const std::filesystem::path& caseDirectory) {
    const KeyReader keys(dictionary);
    keys.checkKnownKeys(dictionary);

    Scene scene;
    scene.caseDirectory = caseDirectory;
    scene.dictionaryFile = dictionary.file();

    // Without a gas (carrier none) there is no fluid, and a lattice start needs no nozzle.
    const bool withGas = keys.word("carrier.type") != "none";
    if (withGas) {
        keys.require("fluid.density", "for a carrier gas");
        keys.require("fluid.kinematicViscosity", "for a carrier gas");
        scene.fluid.density = keys.scalar("fluid.density");
        scene.fluid.kinematicViscosity = keys.scalar("fluid.kinematicViscosity");
    }
    scene.fluid.temperature = keys.scalar("fluid.temperature");

    // With injectors, the nozzle is the analytic jet's only (a mesh or no gas needs none).
    const bool withInjectors = keys.has("injectors");
    const bool analyticGas = withGas && keys.word("carrier.type") != "foamField";
    if (withInjectors ? analyticGas || keys.has("nozzle")
                      : withGas || keys.word("injection.mode") != "lattice") {
        keys.require("nozzle.radius", withGas ? "for a carrier gas" : "to inject on the nozzle");
        scene.nozzle = readDisc(keys, "nozzle");
    }

    scene.carrier = readCarrier(keys, scene.fluid);

    if (!withInjectors) keys.require("particles.count", "to inject on the nozzle");
    scene.particles.count = withInjectors ? 0 : keys.integer("particles.count");
    scene.particles.density = keys.scalar("particles.density");
    scene.particles.radius =
        readRadiusDistribution(keys, "particles.radiusDistribution.", caseDirectory);
    scene.particles.material = readMaterial(keys, "particles.material");
    scene.injection.seed = static_cast<std::uint64_t>(keys.integer("injection.seed"));
    if (withInjectors) {
        scene.injectors = readInjectors(keys, dictionary, scene);
        for (const InjectorSettings& injector : scene.injectors)
            scene.particles.count += injector.count;
        if (!keys.has("nozzle")) scene.nozzle = scene.injectors.front().nozzle;
    } else {
        keys.require("injection", "without injectors");
    }

    scene.injection.mode = *valueNamed(injectionModeNames(), keys.word("injection.mode"));
    if (!withInjectors && scene.injection.mode == InjectionMode::rate) {
        keys.require("injection.rate", "for injection mode rate");
        scene.injection.rate = keys.scalar("injection.rate");
    }
    if (!withInjectors && scene.injection.mode == InjectionMode::lattice) {
        const std::string lattice = "injection.latticeCoeffs";
        keys.require(lattice, "for injection mode lattice");
        scene.injection.latticeOrigin = keys.vector(lattice + ".origin");
        scene.injection.latticeSpacing = keys.scalar(lattice + ".spacing");
        scene.injection.latticeSites = keys.integerTriple(lattice + ".sites");
        scene.injection.latticeVelocitySpread = keys.scalar(lattice + ".velocitySpread");
        const auto& sites = scene.injection.latticeSites;
        if (static_cast<double>(scene.particles.count) >
            static_cast<double>(sites[0]) * sites[1] * sites[2])
            keys.fail(lattice + ".sites", "hold fewer sites than particles.count");
    }
    scene.injection.crossSpanSpeed = keys.scalar("injection.crossSpanSpeed");
    scene.injection.reinjectEscaped = keys.boolean("injection.reinjectEscaped");
    if (scene.injection.reinjectEscaped && scene.injection.mode == InjectionMode::lattice)
        keys.fail("injection.reinjectEscaped", "a lattice's sites are filled once");

    scene.physics.drag = *valueNamed(dragModelNames(), keys.word("physics.drag"));
    scene.physics.gravity = keys.vector("physics.gravity");
    scene.physics.buoyancy = keys.boolean("physics.buoyancy");
    scene.physics.autoThreshold = keys.scalar("physics.autoThreshold");
    readUnsteadyForces(keys, scene);
    readDispersionAndHeat(keys, scene);
    readElectromagnetic(keys, scene.physics, scene.injection.seed);

    if (scene.carrier.type == CarrierType::none)
        keys.require("time.dt", "for carrier type none (no gas for the scene analysis)");
    scene.time.dt = keys.optionalScalar("time.dt").value_or(0);
    scene.time.endTime = keys.scalar("time.endTime");
    if (scene.time.dt > scene.time.endTime) keys.fail("time.dt", "is longer than time.endTime");
    scene.time.stopWhenAllDone = keys.boolean("time.stopWhenAllDone");
    scene.time.integrator = *valueNamed(integratorNames(), keys.word("time.integrator"));
    scene.time.tolerance = keys.scalar("time.tolerance");
    if (scene.time.tolerance >= 1)
        keys.fail("time.tolerance", "must be below 1 (a relative error)");
    if (keys.has("time.tolerance") && scene.time.integrator != Integrator::adaptiveRungeKutta)
        keys.fail("time.tolerance",
                  "controls the steps of adaptiveRungeKutta only, and "
                  "time.integrator is " +
                      std::string(nameOf(integratorNames(), scene.time.integrator)));
    if (scene.time.integrator == Integrator::adaptiveRungeKutta) {
        // The Maxey–Riley step (history window, added mass, ...) advances by whole steps of dt.
        if (scene.physics.unsteadyForces())
            keys.fail("time.integrator",
                      "adaptiveRungeKutta does not take the unsteady forces (history, added "
                      "mass, pressure gradient, lift, spin, Faxén), whose step is a whole dt: "
                      "set them off, or use exponentialMidpoint");
        leaveUnsteadyForcesOff(scene.physics, "not with time.integrator adaptiveRungeKutta");
    }
    if (!scene.physics.electromagnetic.uniform() &&
        scene.time.integrator == Integrator::adaptiveRungeKutta)
        keys.fail("time.integrator",
                  "the coils' fields vary along a step, which adaptiveRungeKutta's sub-steps do "
                  "not sample: set exponentialMidpoint");
    if (scene.physics.electromagnetic.on() &&
        scene.time.integrator != Integrator::exponentialMidpoint &&
        scene.time.integrator != Integrator::adaptiveRungeKutta)
        keys.fail("time.integrator", "the Lorentz step (physics.electromagnetic) is an "
                                     "exponential midpoint rule: set exponentialMidpoint (or "
                                     "adaptiveRungeKutta)");

    const Dictionary& surfaces = dictionary.subDict("surfaces");
    for (const auto& name : surfaces.keys()) {
        const std::string base = "surfaces." + name;
        Surface surface;
        surface.name = name;
        if (keys.word(base + ".type") == "patch") {
            surface.patch = readPatchName(keys, base, scene);
        } else {
            keys.require(base + ".point", "for a plane");
            keys.require(base + ".normal", "for a plane");
            surface.point = keys.vector(base + ".point");
            surface.normal = keys.direction(base + ".normal");
        }
        surface.material = readMaterial(keys, base + ".material");
        surface.interaction =
            *valueNamed(surfaceInteractionNames(), keys.word(base + ".interaction"));
        if (surface.interaction == SurfaceInteraction::erode)
            surface.erosion = readErosion(keys, base, surface);
        scene.surfaces.push_back(surface);
    }
    readCollisionsAndDeposition(keys, scene);
    readSpecies(keys, scene);
    requireFileStatesKept(keys, scene);
    for (const Surface& surface : scene.surfaces)
        if (!surface.patch.empty() && meetsBySoftContact(scene.collisions, surface.interaction))
            keys.fail("surfaces." + surface.name + ".interaction",
                      "a patch cannot be a soft wall of collisions.model softSphere (soft walls "
                      "are planes); use a plane, or interaction deposit or absorb");
    if (scene.carrier.type == CarrierType::none) refuseGasTerms(keys, scene);

    scene.domainFromCarrier = !keys.has("domain");
    if (scene.carrier.type != CarrierType::foamField)
        keys.require("domain", "for an analytic carrier");
    if (!scene.domainFromCarrier) readDomain(keys, scene);
    if (scene.carrier.type == CarrierType::planePoiseuille) requireBoundedChannelFlow(keys, scene);

    scene.output.interval = keys.scalar("output.interval");
    scene.output.carrierResolution = keys.integerTriple("output.carrierResolution");
    scene.output.fields = ParticleFieldSet();
    for (const auto& name : keys.wordList("output.fields"))
        scene.output.fields.add(*valueNamed(particleFieldNames(), name));
    scene.output.hdf5 = keys.boolean("output.hdf5");
    if (keys.has("output.fields") && scene.output.fields.contains(ParticleField::temperature) &&
        scene.physics.heatTransfer == HeatTransferModel::none)
        keys.fail("output.fields", "temperature needs physics.heatTransfer.model");
    const auto& automatic = scene.physics.automaticTerms;
    const bool spinMayTurnOn = std::any_of(automatic.begin(), automatic.end(), [](const auto& a) {
        return a.term == PhysicsTerm::spin || a.term == PhysicsTerm::spinLift;
    });
    if (keys.has("output.fields") && scene.output.fields.contains(ParticleField::angularVelocity) &&
        !tracksSpin(scene) && !spinMayTurnOn)
        keys.fail("output.fields", "angularVelocity needs the particles' spin: physics.spin on, "
                                   "collisions, or a surface that rebounds or deposits");
    return scene;
}

int keyLine(const std::filesystem::path& dictionaryFile, const std::string& path) {
    return KeyReader(Dictionary::parseFile(dictionaryFile)).lineOf(path);
}

Scene readScene(const std::filesystem::path& caseDirectory) {
    const auto file = caseDirectory / "constant" / "slidesProperties";
    return sceneFromDictionary(Dictionary::parseFile(file), caseDirectory);
}

} // namespace slides
