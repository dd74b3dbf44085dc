// PvdSeries: a ParaView collection file (.pvd) listing the frames of a time series.
//
//     <VTKFile type="Collection" version="0.1"><Collection>
//       <DataSet timestep="0.0005" part="0" file="particles_000001.vtp"/> ...
// Rewritten atomically after every frame, so a stopped run leaves a valid series of the
// frames written so far. ParaView opens it as one time-dependent dataset with a time slider.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <utility>

namespace slides {

class PvdSeries {
public:
    /// file: the .pvd to (re)write; frame files are given relative to its directory.
    explicit PvdSeries(std::filesystem::path file);

    /// Appends a frame at time [s] (written with 17 significant digits, so it reads back
    /// bit for bit) and rewrites the collection; throws OutputError, the series unchanged.
    void add(double time, const std::string& relativeFile);
    /// Replaces the series by these (time, file) frames and rewrites it (restart).
    void resume(std::span<const std::pair<double, std::string>> frames);

    const std::filesystem::path& file() const { return file_; }

private:
    static std::string dataSetLine(double time, const std::string& relativeFile);

    std::filesystem::path file_;
    std::string dataSets_; ///< the <DataSet/> lines written so far
};

} // namespace slides
