#include "slides/io/vtk_particles.h"

#include "slides/core/particle_cloud.h"
#include "slides/io/vtk_writing.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>
#include <vtkXMLPolyDataWriter.h>

#include <stdexcept>

namespace slides {

namespace {

/// A VTK array of `values` that reads them in place, without a copy: the writer only reads
/// its input, and `values` outlives it.
vtkSmartPointer<vtkDoubleArray> vectorsInPlace(const char* name, std::span<const Vec3> values) {
    auto array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(name);
    array->SetNumberOfComponents(3);
    static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 is three doubles in a row");
    array->SetArray(const_cast<double*>(reinterpret_cast<const double*>(values.data())),
                    static_cast<vtkIdType>(3 * values.size()), 1 /* VTK does not free it */);
    return array;
}

} // namespace

void writeParticlesVtp(const std::filesystem::path& file, const ParticleFrame& frame) {
    if (!frame.consistent())
        throw std::invalid_argument("writeParticlesVtp: the frame's arrays differ in length");
    const std::size_t size = frame.id.size();
    const auto count = static_cast<vtkIdType>(size);
    vtkNew<vtkPoints> points;
    points->SetData(vectorsInPlace("Points", frame.position));
    vtkNew<vtkCellArray> vertices;
    vertices->AllocateExact(count, count);
    vtkNew<vtkTypeInt64Array> id;
    id->SetName("id");
    id->SetNumberOfValues(count);
    auto diameter = namedDoubleArray("diameter", 1, count);
    auto velocity = vectorsInPlace("velocity", frame.velocity);
    auto speed = namedDoubleArray("speed", 1, count);
    vtkNew<vtkTypeInt32Array> state;
    state->SetName("state");
    state->SetNumberOfValues(count);
    for (vtkIdType i = 0; i < count; ++i) {
        const auto k = static_cast<std::size_t>(i);
        vertices->InsertNextCell(1, &i);
        id->SetValue(i, static_cast<vtkTypeInt64>(frame.id[k]));
        diameter->SetValue(i, particleDiameter(frame.radius[k]));
        speed->SetValue(i, frame.velocity[k].norm());
        state->SetValue(i, frame.state[k]);
    }
    vtkNew<vtkPolyData> polyData;
    polyData->SetPoints(points);
    polyData->SetVerts(vertices);
    auto* data = polyData->GetPointData();
    const auto add = [&](ParticleField field, vtkDataArray* array) {
        if (frame.fields.contains(field)) data->AddArray(array);
    };
    add(ParticleField::id, id);
    add(ParticleField::diameter, diameter);
    add(ParticleField::velocity, velocity);
    add(ParticleField::speed, speed);
    add(ParticleField::state, state);
    if (frame.temperature) {
        auto temperature = namedDoubleArray("temperature", 1, count);
        for (vtkIdType i = 0; i < count; ++i)
            temperature->SetValue(i, (*frame.temperature)[static_cast<std::size_t>(i)]);
        add(ParticleField::temperature, temperature);
    }
    if (frame.angularVelocity) {
        auto spin = namedDoubleArray("angularVelocity", 3, count);
        for (vtkIdType i = 0; i < count; ++i)
            spin->SetTypedTuple(i, (*frame.angularVelocity)[static_cast<std::size_t>(i)].data());
        add(ParticleField::angularVelocity, spin);
    }
    data->SetActiveScalars("speed");
    data->SetActiveVectors("velocity");

    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(polyData);
    writeVtkAtomically(file, writer);
}

} // namespace slides
