#include "slides/io/vtk_damage.h"

#include "slides/io/atomic_file.h"
#include "slides/io/hdf5_file.h"
#include "slides/io/vtk_writing.h"

#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataWriter.h>

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace slides {

void writeDamageVti(const std::filesystem::path& file, const ErosionGrid& grid, double time) {
    const auto points = grid.points();
    const auto count = static_cast<vtkIdType>(grid.damage().size());
    auto damage = namedDoubleArray("damage", 1, count);
    auto peak = namedDoubleArray("peakSigmaEq", 1, count);
    for (vtkIdType n = 0; n < count; ++n) {
        damage->SetValue(n, grid.damage()[static_cast<std::size_t>(n)]);
        peak->SetValue(n, grid.peakEquivalentStress()[static_cast<std::size_t>(n)]);
    }
    auto timeValue = namedDoubleArray("TimeValue", 1, 1);
    timeValue->SetValue(0, time);
    vtkNew<vtkImageData> image;
    image->SetDimensions(points.data());
    image->SetOrigin(grid.origin().data());
    image->SetSpacing(grid.spacing().data());
    const Mat3& axes = grid.axes();
    image->SetDirectionMatrix(axes(0, 0), axes(0, 1), axes(0, 2), axes(1, 0), axes(1, 1),
                              axes(1, 2), axes(2, 0), axes(2, 1), axes(2, 2));
    image->GetPointData()->AddArray(damage);
    image->GetPointData()->AddArray(peak);
    image->GetPointData()->SetActiveScalars("damage");
    image->GetFieldData()->AddArray(timeValue);
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetInputData(image);
    writeVtkAtomically(file, writer);
}

DamageOutput::DamageOutput(std::filesystem::path directory, const std::vector<Surface>& surfaces)
    : directory_(std::move(directory)) {
    for (const Surface& surface : surfaces) {
        names_.push_back(surface.name);
        series_.push_back(
            surface.interaction == SurfaceInteraction::erode
                ? std::optional<PvdSeries>(directory_ / ("damage_" + surface.name + ".pvd"))
                : std::nullopt);
    }
    if (std::none_of(series_.begin(), series_.end(), [](const auto& s) { return s.has_value(); }))
        series_.clear();
}

void DamageOutput::writeFrame(double time, const std::vector<std::optional<ErosionGrid>>& grids) {
    for (std::size_t s = 0; s < series_.size(); ++s) {
        if (!series_[s]) continue;
        char number[16];
        std::snprintf(number, sizeof number, "_%06zu.vti", frames_);
        const std::string name = "damage_" + names_[s] + number;
        writeDamageVti(directory_ / name, *grids[s], time);
        series_[s]->add(time, name);
    }
    ++frames_;
}

nlohmann::json DamageOutput::finish(const std::vector<std::optional<ErosionGrid>>& grids) const {
    if (series_.empty()) return nullptr;
    nlohmann::json summary = nlohmann::json::object();
    const std::filesystem::path partial = directory_ / "damage.h5.partial";
    {
        Hdf5File file(partial);
        for (std::size_t s = 0; s < series_.size(); ++s) {
            if (!series_[s]) continue;
            const ErosionGrid& grid = *grids[s];
            const Hdf5Handle group = file.createGroup("/" + names_[s]);
            const std::vector<std::uint64_t> damage(grid.damage().begin(), grid.damage().end());
            file.writeDataset(group.get(), "damage", damage, "impacts");
            file.writeDataset(group.get(), "peakSigmaEq", grid.peakEquivalentStress(), 1, "Pa");
            const auto depths = static_cast<std::size_t>(grid.points()[2]);
            std::vector<double> times, stresses;
            std::vector<double> centrePeak(depths, 0.0);
            for (const auto& impact : grid.centreLineHistory()) {
                times.push_back(impact.time);
                stresses.insert(stresses.end(), impact.equivalentStress.begin(),
                                impact.equivalentStress.end());
                for (std::size_t k = 0; k < depths; ++k)
                    centrePeak[k] = std::max(centrePeak[k], impact.equivalentStress[k]);
            }
            file.writeDataset(group.get(), "centreLineTime", times, 1, "s");
            file.writeDataset(group.get(), "centreLineSigmaEq", stresses, depths, "Pa");
            std::vector<double> depth(depths);
            for (std::size_t k = 0; k < depths; ++k)
                depth[k] = static_cast<double>(k) * grid.spacing().z();
            summary[names_[s]] = {{"impacts", grid.impacts()},
                                  {"damagedVolume", grid.damagedVolume()},
                                  {"accumulatedDamage",
                                   std::accumulate(damage.begin(), damage.end(), std::uint64_t{0})},
                                  {"layerYoungsModulus", grid.layer().youngsModulus},
                                  {"layerPoissonRatio", grid.layer().poissonRatio},
                                  {"centreLineDepth", depth},
                                  {"centreLinePeakSigmaEq", centrePeak}};
        }
        file.close();
    }
    std::filesystem::rename(partial, directory_ / "damage.h5");
    return summary;
}

} // namespace slides
