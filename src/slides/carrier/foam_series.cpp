#include "slides/carrier/foam_series.h"

#include "slides/carrier/foam_file.h"
#include "slides/carrier/gas_records.h"
#include "slides/core/error.h"

#include <algorithm>
#include <cstdlib>

namespace slides {

namespace {

constexpr const char* timesKey = "carrier.foamFieldCoeffs.times";

/// The numeric time directories of the case within range (all without one), by time.
std::vector<std::pair<double, std::filesystem::path>>
timeDirectories(const std::filesystem::path& caseDirectory,
                const std::optional<std::pair<double, double>>& range) {
    std::vector<std::pair<double, std::filesystem::path>> found;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(caseDirectory, error)) {
        if (!entry.is_directory()) continue;
        const std::string name = entry.path().filename().string();
        char* end = nullptr;
        const double time = std::strtod(name.c_str(), &end);
        if (end == name.c_str() || *end) continue;
        const double slack = 1e-12 * std::max(1.0, std::abs(time));
        if (range && (time < range->first - slack || time > range->second + slack)) continue;
        found.emplace_back(time, entry.path());
    }
    std::sort(found.begin(), found.end());
    return found;
}

} // namespace

FoamSeries::FoamSeries(const std::filesystem::path& caseDirectory,
                       const FoamSeriesSettings& settings, const FoamMesh& mesh)
    : mesh_(mesh), weights_(mesh) {
    const auto found = timeDirectories(caseDirectory, settings.range);
    if (found.size() < 2)
        throw InputError(caseDirectory.string(), 0, timesKey,
                         "a time series needs at least two time directories in the range, found " +
                             std::to_string(found.size()));
    hasScalar_ = gasScalarsIn(found.front().second);
    std::vector<double> offsets;
    for (const auto& [time, directory] : found) {
        if (std::filesystem::exists(directory / "polyMesh"))
            throw InputError((directory / "polyMesh").string(), 0, timesKey,
                             "a mesh inside a time directory: moving or changing meshes are not "
                             "supported (the series needs one fixed constant/polyMesh)");
        if (!FoamFile::exists(directory / "U"))
            throw InputError((directory / "U").string(), 0, timesKey,
                             "missing field U in a time directory of the series");
        for (int s = 0; s < 3; ++s)
            if (hasScalar_[s] && !FoamFile::exists(directory / gasScalarNames[s]))
                throw InputError((directory / gasScalarNames[s]).string(), 0, timesKey,
                                 std::string("missing field ") + gasScalarNames[s] + ", which " +
                                     found.front().second.filename().string() + " has");
        offsets.push_back(time - found.front().first);
        directories_.push_back(directory);
    }
    if (settings.cycle && !(*settings.cycle > offsets[1]))
        throw InputError(caseDirectory.string(), 0, "carrier.foamFieldCoeffs.cycle",
                         "the period must exceed the first write interval " +
                             std::to_string(offsets[1]) + " s");
    cache_ = std::make_unique<LevelCache<FoamLevel>>(
        TimeLevels(std::move(offsets), settings.cycle),
        [this](std::size_t index) { return read(index); }, settings.readAhead);
    cache_->hold(0, 0);
}

std::shared_ptr<const FoamLevel> FoamSeries::read(std::size_t index) const {
    return std::make_shared<const FoamLevel>(readGasRecords(directories_[index], mesh_, hasScalar_),
                                             mesh_, weights_);
}

void FoamSeries::hold(double start, double end) {
    const TimeLevels& levels = cache_->levels();
    if (end > levels.end() * (1 + 1e-12))
        throw InputError(directories_.back().string(), 0, timesKey,
                         "the run reaches t = " + std::to_string(end) +
                             " s, beyond the series' last level (" + std::to_string(levels.end()) +
                             " s after the first): shorten time.endTime or set cycle");
    cache_->hold(start, std::min(end, levels.end()));
}

LevelCache<FoamLevel>::Pair FoamSeries::at(double time) {
    return cache_->at(std::min(time, cache_->levels().end()));
}

} // namespace slides
