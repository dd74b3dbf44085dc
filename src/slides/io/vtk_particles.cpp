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

void writeParticlesVtp(const std::filesystem::path& file, const ParticleFrame& frame) {
    if (!frame.consistent())
        throw std::invalid_argument("writeParticlesVtp: the frame's arrays differ in length");
    const std::size_t size = frame.id.size();
    const auto count = static_cast<vtkIdType>(size);
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(count);
    vtkNew<vtkCellArray> vertices;
    vertices->AllocateExact(count, count);
    vtkNew<vtkTypeInt64Array> id;
    id->SetName("id");
    id->SetNumberOfValues(count);
    auto diameter = namedDoubleArray("diameter", 1, count);
    auto velocity = namedDoubleArray("velocity", 3, count);
    auto speed = namedDoubleArray("speed", 1, count);
    vtkNew<vtkTypeInt32Array> state;
    state->SetName("state");
    state->SetNumberOfValues(count);
    for (vtkIdType i = 0; i < count; ++i) {
        const auto k = static_cast<std::size_t>(i);
        points->SetPoint(i, frame.position[k].data());
        vertices->InsertNextCell(1, &i);
        id->SetValue(i, static_cast<vtkTypeInt64>(frame.id[k]));
        diameter->SetValue(i, particleDiameter(frame.radius[k]));
        velocity->SetTypedTuple(i, frame.velocity[k].data());
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
    if (frame.injector) {
        vtkNew<vtkTypeInt32Array> injector;
        injector->SetName("injector");
        injector->SetNumberOfValues(count);
        for (vtkIdType i = 0; i < count; ++i)
            injector->SetValue(i, (*frame.injector)[static_cast<std::size_t>(i)]);
        data->AddArray(injector);
    }
    data->SetActiveScalars("speed");
    data->SetActiveVectors("velocity");

    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(polyData);
    writeVtkAtomically(file, writer);
}

} // namespace slides
