#include "slides/io/xdmf_particles.h"

#include <cstdio>
#include <sstream>

namespace slides {

namespace {

struct XdmfArray {
    ParticleField field;
    const char* name;
    const char* attributeType; ///< Scalar or Vector
    const char* numberType;    ///< Float, Int or UInt
    int precision;             ///< bytes
    int components;
};

constexpr XdmfArray xdmfArrays[] = {
    {ParticleField::id, "id", "Scalar", "UInt", 8, 1},
    {ParticleField::diameter, "diameter", "Scalar", "Float", 8, 1},
    {ParticleField::velocity, "velocity", "Vector", "Float", 8, 3},
    {ParticleField::speed, "speed", "Scalar", "Float", 8, 1},
    {ParticleField::state, "state", "Scalar", "Int", 4, 1},
    {ParticleField::temperature, "temperature", "Scalar", "Float", 8, 1},
    {ParticleField::angularVelocity, "angularVelocity", "Vector", "Float", 8, 3},
};

std::string dimensions(std::size_t count, int components) {
    return components == 1 ? std::to_string(count)
                           : std::to_string(count) + " " + std::to_string(components);
}

} // namespace

std::string particlesXdmf(std::string_view hdf5File, std::span<const XdmfFrame> frames) {
    std::ostringstream xml;
    xml << "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
        << "<Xdmf Version=\"2.0\">\n  <Domain>\n"
        << "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const auto& frame : frames) {
        if (frame.count == 0) continue;
        const std::string source = std::string(hdf5File) + ":" + frame.group + "/";
        char time[32];
        std::snprintf(time, sizeof time, "%.17g", frame.time);
        xml << "      <Grid Name=\"" << frame.group << "\" GridType=\"Uniform\">\n"
            << "        <Time Value=\"" << time << "\"/>\n"
            << "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << frame.count
            << "\" NodesPerElement=\"1\"/>\n"
            << "        <Geometry GeometryType=\"XYZ\">\n"
            << "          <DataItem Dimensions=\"" << dimensions(frame.count, 3)
            << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << source
            << "position</DataItem>\n        </Geometry>\n";
        for (const auto& array : xdmfArrays) {
            if (!frame.fields.contains(array.field)) continue;
            xml << "        <Attribute Name=\"" << array.name << "\" AttributeType=\""
                << array.attributeType << "\" Center=\"Node\">\n"
                << "          <DataItem Dimensions=\"" << dimensions(frame.count, array.components)
                << "\" NumberType=\"" << array.numberType << "\" Precision=\"" << array.precision
                << "\" Format=\"HDF\">" << source << array.name << "</DataItem>\n"
                << "        </Attribute>\n";
        }
        xml << "      </Grid>\n";
    }
    xml << "    </Grid>\n  </Domain>\n</Xdmf>\n";
    return xml.str();
}

} // namespace slides
