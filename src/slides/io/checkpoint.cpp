#include "slides/io/checkpoint.h"

#include "slides/core/error.h"
#include "slides/io/atomic_file.h"
#include "slides/io/hdf5_file.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>

namespace slides {

namespace fs = std::filesystem;

namespace {

constexpr const char* group = "/checkpoint";

std::string hex(std::uint64_t value) {
    char text[20];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
    return text;
}

/// The shortest text that reads back as exactly this value.
std::string shortest(double value) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, value).ptr;
    return std::string(text, end);
}

/// FNV-1a, 64 bit: a stable hash of the dictionary's bytes (std::hash is not stable).
std::uint64_t fnv1a(const std::string& bytes) {
    std::uint64_t hash = 14695981039346656037ULL;
    for (const unsigned char byte : bytes) hash = (hash ^ byte) * 1099511628211ULL;
    return hash;
}

// One column per per-particle array type; units are SI, as everywhere.
void writeColumn(const Hdf5File& file, hid_t parent, const std::string& name,
                 const std::vector<std::uint64_t>& values) {
    file.writeDataset(parent, name, values, "1");
}
void writeColumn(const Hdf5File& file, hid_t parent, const std::string& name,
                 const std::vector<std::int32_t>& values) {
    file.writeDataset(parent, name, values, "1");
}
void writeColumn(const Hdf5File& file, hid_t parent, const std::string& name,
                 const std::vector<double>& values) {
    file.writeDataset(parent, name, values, 1, "SI");
}
void writeColumn(const Hdf5File& file, hid_t parent, const std::string& name,
                 const std::vector<Vec3>& values) {
    file.writeDataset(parent, name, std::span<const Vec3>(values), "SI");
}

/// An eddy state as six numbers: the standardised fluctuation, time and length left, and the
/// event counter (exact as a double below 2⁵³).
void writeColumn(const Hdf5File& file, hid_t parent, const std::string& name,
                 const std::vector<EddyState>& values) {
    std::vector<double> flat;
    for (const EddyState& eddy : values)
        flat.insert(flat.end(),
                    {eddy.standardised.x(), eddy.standardised.y(), eddy.standardised.z(),
                     eddy.timeLeft, eddy.lengthLeft, static_cast<double>(eddy.count)});
    file.writeDataset(parent, name, flat, 6, "SI");
}

void readColumn(const Hdf5File& file, const std::string& path, std::vector<std::uint64_t>& out) {
    out = file.readUInt64(path);
}
void readColumn(const Hdf5File& file, const std::string& path, std::vector<std::int32_t>& out) {
    out = file.readInt32(path);
}
void readColumn(const Hdf5File& file, const std::string& path, std::vector<double>& out) {
    out = file.readDoubles(path, 1);
}
void readColumn(const Hdf5File& file, const std::string& path, std::vector<EddyState>& out) {
    const auto flat = file.readDoubles(path, 6);
    out.resize(flat.size() / 6);
    for (std::size_t i = 0; i < out.size(); ++i) {
        const double* e = &flat[6 * i];
        out[i] = {Vec3(e[0], e[1], e[2]), e[3], e[4], static_cast<std::uint32_t>(e[5])};
    }
}

void readColumn(const Hdf5File& file, const std::string& path, std::vector<Vec3>& out) {
    const auto flat = file.readDoubles(path, 3);
    out.resize(flat.size() / 3);
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = Vec3(flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]);
}

/// The arrivals as columns, in order.
struct ArrivalColumns {
    std::vector<std::uint64_t> id;
    std::vector<std::int32_t> surface;
    std::vector<double> time, radius, temperature;
    std::vector<Vec3> position, velocity, angularVelocity;

    template <typename Columns, typename Visitor> static void forEach(Columns& c, Visitor visit) {
        visit("id", c.id);
        visit("surface", c.surface);
        visit("time", c.time);
        visit("position", c.position);
        visit("velocity", c.velocity);
        visit("radius", c.radius);
        visit("temperature", c.temperature);
        visit("angularVelocity", c.angularVelocity);
    }
};

void writeState(const Hdf5File& file, const RunSnapshot& snapshot, const SpringColumns* springs,
                const std::vector<FrameRecord>& frames, double nextFrameTime, const RunTimes& times,
                const RunFingerprint& fingerprint) {
    const Hdf5Handle checkpoint = file.createGroup(group);
    const hid_t g = checkpoint.get();
    file.writeAttribute(g, "version", fingerprint.version);
    file.writeAttribute(g, "dictionaryHash", hex(fingerprint.dictionaryHash));
    file.writeAttribute(g, "dt", fingerprint.dt);
    const RunCounters& counters = snapshot.counters;
    file.writeAttribute(g, "time", counters.time);
    file.writeAttribute(g, "steps", std::int64_t{counters.steps});
    file.writeAttribute(g, "injected", std::int64_t{counters.injected});
    file.writeAttribute(g, "escaped", std::int64_t{counters.escaped});
    file.writeAttribute(g, "particleSteps", static_cast<std::int64_t>(counters.particleSteps));
    file.writeAttribute(g, "collisions", std::int64_t{counters.collisions});
    writeColumn(file, g, "rebounds", counters.rebounds);
    file.writeAttribute(g, "nextFrameTime", nextFrameTime);
    file.writeAttribute(g, "wallSeconds", times.wallSeconds);
    file.writeAttribute(g, "steppingSeconds", times.steppingSeconds);
    writeColumn(file, g, "escapedThrough", counters.escapedThrough);
    writeColumn(file, g, "reinjected", counters.reinjected);

    const Hdf5Handle cloud = file.createGroup(std::string(group) + "/cloud");
    ParticleCloud::forEachArray(snapshot.cloud, [&](const char* name, const auto& array) {
        writeColumn(file, cloud.get(), name, array);
    });
    const std::size_t width = snapshot.cloud.stateWidth;
    file.writeAttribute(cloud.get(), "stateWidth", static_cast<std::int64_t>(width));
    file.writeDataset(cloud.get(), "modelState", snapshot.cloud.modelState,
                      std::max<std::size_t>(width, 1), "SI");
    ArrivalColumns arrivals;
    for (const Arrival& arrival : snapshot.arrivals) {
        arrivals.id.push_back(arrival.id);
        arrivals.surface.push_back(arrival.surface);
        arrivals.time.push_back(arrival.time);
        arrivals.radius.push_back(arrival.radius);
        arrivals.position.push_back(arrival.position);
        arrivals.velocity.push_back(arrival.velocity);
        arrivals.temperature.push_back(arrival.temperature);
        arrivals.angularVelocity.push_back(arrival.angularVelocity);
    }
    const Hdf5Handle arrived = file.createGroup(std::string(group) + "/arrivals");
    ArrivalColumns::forEach(arrivals, [&](const char* name, const auto& array) {
        writeColumn(file, arrived.get(), name, array);
    });
    if (springs) {
        const Hdf5Handle contacts = file.createGroup(std::string(group) + "/springs");
        SpringColumns::forEach(*springs, [&](const char* name, const auto& array) {
            writeColumn(file, contacts.get(), name, array);
        });
    }
    std::vector<double> frameTimes;
    std::vector<std::uint64_t> frameCounts;
    for (const auto& frame : frames) {
        frameTimes.push_back(frame.time);
        frameCounts.push_back(frame.count);
    }
    writeColumn(file, g, "frameTimes", frameTimes);
    writeColumn(file, g, "frameCounts", frameCounts);
}

[[noreturn]] void refuse(const fs::path& file, const std::string& why) {
    throw InputError(file.string(), 0, "", why + "; cannot restart from it");
}

bool finite(double value) { return std::isfinite(value); }
bool finite(const Vec3& value) { return value.allFinite(); }
template <typename Value> bool finite(const std::vector<Value>& values) {
    return std::all_of(values.begin(), values.end(), [](const Value& v) { return finite(v); });
}

/// Refuses a state value that no run can hold (a NaN or infinity where the run needs a number),
/// so that it never enters a run.
template <typename Value>
void requireFinite(const Hdf5File& file, const std::string& what, const Value& value) {
    if (!finite(value)) refuse(file.path(), "damaged: non-finite value in " + what);
}

CheckpointState readState(const Hdf5File& file, const RunFingerprint& expected) {
    const std::string g = group;
    if (!file.exists(g)) refuse(file.path(), "not a checkpoint (no " + g + " group)");
    const std::string version = file.readText(g, "version");
    if (version != expected.version)
        refuse(file.path(), "written by SLIDES-track " + version + ", this is " + expected.version);
    const std::string hash = file.readText(g, "dictionaryHash");
    if (hash != hex(expected.dictionaryHash))
        refuse(file.path(), "written for another case dictionary (hash " + hash +
                                ", constant/slidesProperties now hashes to " +
                                hex(expected.dictionaryHash) + ")");
    const double dt = file.readDouble(g, "dt");
    requireFinite(file, g + " dt", dt);
    if (dt != expected.dt)
        refuse(file.path(), "written with dt = " + shortest(dt) +
                                " s, this run has dt = " + shortest(expected.dt) + " s");

    CheckpointState state;
    state.counters.time = file.readDouble(g, "time");
    state.counters.steps = file.readInt64(g, "steps");
    state.counters.injected = file.readInt64(g, "injected");
    state.counters.escaped = file.readInt64(g, "escaped");
    state.counters.particleSteps = static_cast<std::uint64_t>(file.readInt64(g, "particleSteps"));
    state.counters.collisions = file.readInt64(g, "collisions");
    state.counters.rebounds = file.readUInt64(g + "/rebounds");
    state.nextFrameTime = file.readDouble(g, "nextFrameTime");
    state.times = {file.readDouble(g, "wallSeconds"), file.readDouble(g, "steppingSeconds")};
    for (const double value : {state.counters.time, state.nextFrameTime, state.times.wallSeconds,
                               state.times.steppingSeconds})
        requireFinite(file, g + " times", value);
    if (state.counters.steps < 0 || state.counters.injected < 0 || state.counters.escaped < 0 ||
        state.counters.collisions < 0)
        refuse(file.path(), "damaged: negative counter in " + g);
    state.counters.escapedThrough = file.readUInt64(g + "/escapedThrough");
    // A checkpoint from before re-injection: a run that re-injects nothing.
    if (file.exists(g + "/reinjected"))
        state.counters.reinjected = file.readUInt64(g + "/reinjected");

    const std::size_t count = file.readUInt64(g + "/cloud/id").size();
    ParticleCloud::forEachArray(state.cloud, [&](const char* name, auto& array) {
        // A checkpoint from before the charge array holds uncharged particles.
        if (std::string_view(name) == "charge" && !file.exists(g + "/cloud/charge")) return;
        readColumn(file, g + "/cloud/" + name, array);
        if (!array.empty() && array.size() != count)
            refuse(file.path(), std::string("damaged: cloud array ") + name + " has " +
                                    std::to_string(array.size()) + " entries, not " +
                                    std::to_string(count));
    });
    requireFinite(file, g + "/cloud/position", state.cloud.position);
    requireFinite(file, g + "/cloud/velocity", state.cloud.velocity);
    requireFinite(file, g + "/cloud/radius", state.cloud.radius);
    requireFinite(file, g + "/cloud/temperature", state.cloud.temperature);
    requireFinite(file, g + "/cloud/angularVelocity", state.cloud.angularVelocity);
    state.cloud.stateWidth = static_cast<std::size_t>(file.readInt64(g + "/cloud", "stateWidth"));
    state.cloud.modelState =
        file.readDoubles(g + "/cloud/modelState", std::max<std::size_t>(state.cloud.stateWidth, 1));
    if (state.cloud.modelState.size() != count * state.cloud.stateWidth)
        refuse(file.path(), "damaged: model state does not match the particles");
    ArrivalColumns arrivals;
    ArrivalColumns::forEach(arrivals, [&](const char* name, auto& array) {
        readColumn(file, g + "/arrivals/" + name, array);
        if (array.size() != arrivals.id.size())
            refuse(file.path(), std::string("damaged: arrival column ") + name + " has " +
                                    std::to_string(array.size()) + " entries, not " +
                                    std::to_string(arrivals.id.size()));
        requireFinite(file, g + "/arrivals/" + name, array);
    });
    for (std::size_t i = 0; i < arrivals.id.size(); ++i)
        state.arrivals.push_back({arrivals.id[i], arrivals.surface[i], arrivals.time[i],
                                  arrivals.position[i], arrivals.velocity[i], arrivals.radius[i],
                                  arrivals.temperature[i], arrivals.angularVelocity[i]});
    if (file.exists(g + "/springs")) {
        SpringColumns& springs = state.springs;
        SpringColumns::forEach(springs, [&](const char* name, auto& array) {
            // A checkpoint from before the column: no contact law that unloads from its largest
            // overlap (waltonBraun) existed, so every δ_max is unused; 0.
            if (std::string_view(name) == "largestOverlap" &&
                !file.exists(g + "/springs/largestOverlap"))
                return;
            readColumn(file, g + "/springs/" + name, array);
        });
        if (!file.exists(g + "/springs/largestOverlap"))
            springs.largestOverlap.assign(springs.first.size(), 0.0);
        if (springs.second.size() != springs.first.size() ||
            springs.displacement.size() != springs.first.size() ||
            springs.largestOverlap.size() != springs.first.size())
            refuse(file.path(), "damaged: contact spring columns differ in length");
    }
    const auto frameTimes = file.readDoubles(g + "/frameTimes", 1);
    const auto frameCounts = file.readUInt64(g + "/frameCounts");
    if (frameTimes.size() != frameCounts.size()) refuse(file.path(), "damaged: frame lists differ");
    for (std::size_t n = 0; n < frameTimes.size(); ++n)
        state.frames.push_back({frameTimes[n], frameCounts[n]});
    return state;
}

} // namespace

RunFingerprint fingerprintOf(const fs::path& dictionaryFile, double dt) {
    std::ifstream in(dictionaryFile, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    return {SLIDES_VERSION, fnv1a(bytes), dt};
}

void writeCheckpoint(const fs::path& directory, const RunSnapshot& snapshot,
                     const SpringColumns* springs, const std::vector<FrameRecord>& frames,
                     double nextFrameTime, const RunTimes& times,
                     const RunFingerprint& fingerprint) {
    writeFileAtomically(directory / checkpointFileName, [&](const fs::path& temporary) {
        Hdf5File file(temporary, Hdf5Access::createChecksummed);
        writeState(file, snapshot, springs, frames, nextFrameTime, times, fingerprint);
        file.close();
    });
}

CheckpointState readCheckpoint(const fs::path& directory, const RunFingerprint& fingerprint) {
    const fs::path path = directory / checkpointFileName;
    if (!fs::exists(path)) refuse(path, "no checkpoint here (write one with --checkpoint-every N)");
    const Hdf5File file(path, Hdf5Access::readOnly);
    return readState(file, fingerprint);
}

} // namespace slides
