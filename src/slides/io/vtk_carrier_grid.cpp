#include "slides/io/vtk_carrier_grid.h"

#include "slides/io/vtk_writing.h"

#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataWriter.h>

#include <stdexcept>
#include <vector>

namespace slides {

namespace {

Vec3 latticeSpacing(const Box& box, std::array<int, 3> pointsPerAxis) {
    Vec3 spacing;
    for (int axis = 0; axis < 3; ++axis) {
        if (pointsPerAxis[axis] < 1)
            throw std::invalid_argument("writeCarrierVti: an axis has no lattice points");
        spacing[axis] = pointsPerAxis[axis] > 1
                            ? (box.max[axis] - box.min[axis]) / (pointsPerAxis[axis] - 1)
                            : 1.0;
    }
    return spacing;
}

} // namespace

CarrierSample sampleCarrierLattice(const CarrierField& carrier, const Box& box,
                                   std::array<int, 3> pointsPerAxis, double time) {
    const Vec3 spacing = latticeSpacing(box, pointsPerAxis);
    // VTK orders lattice points with x fastest, then y, then z.
    std::vector<Vec3> points;
    points.reserve(static_cast<std::size_t>(pointsPerAxis[0]) * pointsPerAxis[1] *
                   pointsPerAxis[2]);
    for (int k = 0; k < pointsPerAxis[2]; ++k)
        for (int j = 0; j < pointsPerAxis[1]; ++j)
            for (int i = 0; i < pointsPerAxis[0]; ++i)
                points.push_back(box.min + Vec3(i, j, k).cwiseProduct(spacing));
    CarrierSample gas;
    carrier.sample(points, time, CarrierNeeds{}, gas);
    return gas;
}

void writeCarrierVti(const std::filesystem::path& file, const CarrierField& carrier, const Box& box,
                     std::array<int, 3> pointsPerAxis, double time) {
    const Vec3 spacing = latticeSpacing(box, pointsPerAxis);
    const CarrierSample gas = sampleCarrierLattice(carrier, box, pointsPerAxis, time);
    const auto count = static_cast<vtkIdType>(gas.velocity.size());
    auto velocity = namedDoubleArray("U", 3, count);
    auto speed = namedDoubleArray("magU", 1, count);
    for (vtkIdType n = 0; n < count; ++n) {
        const Vec3& u = gas.velocity[static_cast<std::size_t>(n)];
        velocity->SetTypedTuple(n, u.data());
        speed->SetValue(n, u.norm());
    }
    auto timeValue = namedDoubleArray("TimeValue", 1, 1);
    timeValue->SetValue(0, time);
    vtkNew<vtkImageData> image;
    image->SetDimensions(pointsPerAxis.data());
    image->SetOrigin(box.min.data());
    image->SetSpacing(spacing.data());
    image->GetPointData()->AddArray(velocity);
    image->GetPointData()->AddArray(speed);
    image->GetPointData()->SetActiveVectors("U");
    image->GetPointData()->SetActiveScalars("magU");
    image->GetFieldData()->AddArray(timeValue);

    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetInputData(image);
    writeVtkAtomically(file, writer);
}

} // namespace slides
