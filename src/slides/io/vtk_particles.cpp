#include "slides/io/vtk_particles.h"

#include "slides/core/error.h"
#include "slides/core/particle_cloud.h"
#include "slides/io/vtk_writing.h"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <limits>
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

/// One vertex cell per particle, at its point: offsets 0 … count and connectivity 0 … count − 1
/// in `Index` integers (32-bit ones take 8 B a particle where vtkIdType takes 16).
template <typename IndexArray> void setVertexPerPoint(vtkCellArray& vertices, vtkIdType count) {
    vtkNew<IndexArray> offsets;
    offsets->SetNumberOfValues(count + 1);
    vtkNew<IndexArray> connectivity;
    connectivity->SetNumberOfValues(count);
    for (vtkIdType i = 0; i < count; ++i) {
        offsets->SetValue(i, static_cast<typename IndexArray::ValueType>(i));
        connectivity->SetValue(i, static_cast<typename IndexArray::ValueType>(i));
    }
    offsets->SetValue(count, static_cast<typename IndexArray::ValueType>(count));
    vertices.SetData(offsets, connectivity);
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
    if (count < std::numeric_limits<vtkTypeInt32>::max())
        setVertexPerPoint<vtkTypeInt32Array>(*vertices, count);
    else
        setVertexPerPoint<vtkTypeInt64Array>(*vertices, count);
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
    if (frame.charge) {
        auto charge = namedDoubleArray("charge", 1, count);
        for (vtkIdType i = 0; i < count; ++i)
            charge->SetValue(i, (*frame.charge)[static_cast<std::size_t>(i)]);
        data->AddArray(charge);
    }
    if (frame.injector) {
        vtkNew<vtkTypeInt32Array> injector;
        injector->SetName("injector");
        injector->SetNumberOfValues(count);
        for (vtkIdType i = 0; i < count; ++i)
            injector->SetValue(i, (*frame.injector)[static_cast<std::size_t>(i)]);
        data->AddArray(injector);
    }
    if (frame.density) {
        auto density = namedDoubleArray("density", 1, count);
        for (vtkIdType i = 0; i < count; ++i)
            density->SetValue(i, (*frame.density)[static_cast<std::size_t>(i)]);
        data->AddArray(density);
    }
    data->SetActiveScalars("speed");
    data->SetActiveVectors("velocity");

    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(polyData);
    writeVtkAtomically(file, writer);
}

ParticleFrame StoredParticleFrame::view(ParticleFieldSet fields, bool heating, bool spinning,
                                        bool charged) const {
    ParticleFrame frame{id, position, velocity, radius, state, fields};
    if (heating) frame.temperature = temperature;
    if (spinning) frame.angularVelocity = angularVelocity;
    if (charged) frame.charge = charge;
    return frame;
}

namespace {

/// Values of the named point array with `components` components, or `fallback` per particle
/// when the file does not hold it.
template <typename Value>
std::vector<Value> pointArray(vtkPointData* data, const char* name, int components,
                              std::size_t count, const Value& fallback,
                              const std::filesystem::path& file) {
    std::vector<Value> values(count, fallback);
    vtkDataArray* array = data->GetArray(name);
    if (!array) return values;
    if (array->GetNumberOfComponents() != components ||
        static_cast<std::size_t>(array->GetNumberOfTuples()) != count)
        throw InputError(file.string(), 0, "",
                         std::string("damaged frame: array ") + name + " does not fit its points");
    for (std::size_t i = 0; i < count; ++i) {
        const double* tuple = array->GetTuple(static_cast<vtkIdType>(i));
        if constexpr (std::is_same_v<Value, Vec3>)
            values[i] = Vec3(tuple[0], tuple[1], tuple[2]);
        else
            values[i] = static_cast<Value>(tuple[0]);
    }
    return values;
}

} // namespace

StoredParticleFrame readParticlesVtp(const std::filesystem::path& file) {
    if (!std::filesystem::is_regular_file(file))
        throw InputError(file.string(), 0, "", "missing frame file");
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(file.c_str());
    // VTK reports a damaged file as error events: one InputError below instead of its report.
    bool failed = false;
    vtkNew<vtkCallbackCommand> onError;
    onError->SetClientData(&failed);
    onError->SetCallback(
        [](vtkObject*, unsigned long, void* flag, void*) { *static_cast<bool*>(flag) = true; });
    reader->AddObserver(vtkCommand::ErrorEvent, onError);
    const auto verbosity = vtkLogger::GetCurrentVerbosityCutoff(); // its decompressor's too
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    reader->Update();
    vtkLogger::SetStderrVerbosity(verbosity);
    vtkPolyData* polyData = reader->GetOutput();
    if (failed || !polyData || reader->GetErrorCode() != 0)
        throw InputError(file.string(), 0, "", "damaged frame: VTK cannot read it");
    const auto count = static_cast<std::size_t>(polyData->GetNumberOfPoints());
    vtkPointData* data = polyData->GetPointData();
    StoredParticleFrame frame;
    frame.position.resize(count);
    for (std::size_t i = 0; i < count; ++i)
        polyData->GetPoint(static_cast<vtkIdType>(i), frame.position[i].data());
    // Ids below 2⁵³ pass through the double of GetTuple exactly.
    frame.id = pointArray<std::uint64_t>(data, "id", 1, count, 0, file);
    const auto speed = pointArray<double>(data, "speed", 1, count, 0.0, file);
    frame.velocity = pointArray<Vec3>(data, "velocity", 3, count, Vec3::Zero(), file);
    if (!data->GetArray("velocity"))
        for (std::size_t i = 0; i < count; ++i) frame.velocity[i] = Vec3(speed[i], 0, 0);
    frame.radius = pointArray<double>(data, "diameter", 1, count, 0.0, file);
    for (double& radius : frame.radius) radius /= 2; // exact: particleDiameter doubles it back
    frame.state = pointArray<std::int32_t>(data, "state", 1, count, 0, file);
    frame.temperature = pointArray<double>(data, "temperature", 1, count, 0.0, file);
    frame.angularVelocity = pointArray<Vec3>(data, "angularVelocity", 3, count, Vec3::Zero(), file);
    frame.charge = pointArray<double>(data, "charge", 1, count, 0.0, file);
    return frame;
}

} // namespace slides
