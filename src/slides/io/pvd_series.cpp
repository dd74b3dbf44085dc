#include "slides/io/pvd_series.h"

#include "slides/io/atomic_file.h"

#include <cstdio>

namespace slides {

PvdSeries::PvdSeries(std::filesystem::path file) : file_(std::move(file)) {}

void PvdSeries::add(double time, const std::string& relativeFile) {
    entries_.push_back({time, relativeFile});
    std::string text = "<?xml version=\"1.0\"?>\n"
                       "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                       "  <Collection>\n";
    char timestep[32];
    for (const auto& entry : entries_) {
        std::snprintf(timestep, sizeof timestep, "%.17g", entry.time);
        text += "    <DataSet timestep=\"" + std::string(timestep) + "\" part=\"0\" file=\"" +
                entry.file + "\"/>\n";
    }
    text += "  </Collection>\n</VTKFile>\n";
    writeTextAtomically(file_, text);
}

} // namespace slides
