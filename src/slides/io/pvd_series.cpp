#include "slides/io/pvd_series.h"

#include "slides/io/atomic_file.h"

#include <cstdio>
#include <string_view>

namespace slides {

namespace {

/// text with the characters XML reserves in an attribute value replaced by entities.
std::string xmlAttribute(const std::string& text) {
    std::string escaped;
    for (const char c : text) {
        switch (c) {
        case '&': escaped += "&amp;"; break;
        case '<': escaped += "&lt;"; break;
        case '>': escaped += "&gt;"; break;
        case '"': escaped += "&quot;"; break;
        default: escaped += c;
        }
    }
    return escaped;
}

constexpr std::string_view head = "<?xml version=\"1.0\"?>\n"
                                  "<VTKFile type=\"Collection\" version=\"0.1\" "
                                  "byte_order=\"LittleEndian\">\n"
                                  "  <Collection>\n";
constexpr std::string_view tail = "  </Collection>\n</VTKFile>\n";

} // namespace

PvdSeries::PvdSeries(std::filesystem::path file) : file_(std::move(file)) {}

std::string PvdSeries::dataSetLine(double time, const std::string& relativeFile) {
    char timestep[32];
    std::snprintf(timestep, sizeof timestep, "%.17g", time);
    return std::string("    <DataSet timestep=\"") + timestep + "\" part=\"0\" file=\"" +
           xmlAttribute(relativeFile) + "\"/>\n";
}

void PvdSeries::add(double time, const std::string& relativeFile) {
    std::string dataSets = dataSets_ + dataSetLine(time, relativeFile);
    writeTextAtomically(file_, std::string(head) + dataSets + std::string(tail));
    dataSets_ = std::move(dataSets);
}

void PvdSeries::resume(std::span<const std::pair<double, std::string>> frames) {
    std::string dataSets;
    for (const auto& [time, relativeFile] : frames) dataSets += dataSetLine(time, relativeFile);
    writeTextAtomically(file_, std::string(head) + dataSets + std::string(tail));
    dataSets_ = std::move(dataSets);
}

} // namespace slides
