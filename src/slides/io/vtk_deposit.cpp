#include "slides/io/vtk_deposit.h"

#include "slides/core/particle_cloud.h"
#include "slides/io/vtk_particles.h"
#include "slides/io/vtk_writing.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataWriter.h>

namespace slides {

void writeDepositMapVti(const std::filesystem::path& file, const DepositMap& map) {
    vtkNew<vtkImageData> image;
    image->SetDimensions(map.columns, map.rows, 1);
    image->SetOrigin(map.origin.data());
    image->SetSpacing(map.pixel, map.pixel, map.pixel);
    // Columns of the direction matrix: the lattice's axes in space (u, v, n).
    double direction[9];
    for (int row = 0; row < 3; ++row) {
        direction[3 * row + 0] = map.uAxis[row];
        direction[3 * row + 1] = map.vAxis[row];
        direction[3 * row + 2] = map.normal[row];
    }
    image->SetDirectionMatrix(direction);
    auto height = namedDoubleArray("height", 1, static_cast<vtkIdType>(map.height.size()));
    for (std::size_t k = 0; k < map.height.size(); ++k)
        height->SetValue(static_cast<vtkIdType>(k), map.height[k]);
    image->GetPointData()->AddArray(height);
    image->GetPointData()->SetActiveScalars("height");
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetInputData(image);
    writeVtkAtomically(file, writer);
}

void writeDeposit(const std::filesystem::path& directory, const std::vector<Surface>& surfaces,
                  const std::vector<Arrival>& arrivals) {
    std::vector<std::uint64_t> ids;
    std::vector<Vec3> positions, velocities;
    std::vector<double> radii;
    bool anyDepositSurface = false;
    for (std::size_t s = 0; s < surfaces.size(); ++s) {
        const Surface& plane = surfaces[s];
        if (plane.interaction != SurfaceInteraction::deposit) continue;
        anyDepositSurface = true;
        for (const Arrival& arrival : arrivals)
            if (arrival.surface == static_cast<int>(s)) {
                ids.push_back(arrival.id);
                positions.push_back(arrival.position);
                velocities.push_back(arrival.velocity);
                radii.push_back(arrival.radius);
            }
        const DepositMap map = depositMap(plane, static_cast<int>(s), arrivals);
        if (!map.height.empty())
            writeDepositMapVti(directory / ("deposit_" + plane.name + ".vti"), map);
    }
    if (!anyDepositSurface) return;
    const std::vector<std::int32_t> states(ids.size(),
                                           static_cast<std::int32_t>(ParticleState::arrived));
    ParticleFrame frame{ids, positions, velocities, radii, states};
    writeParticlesVtp(directory / "deposit.vtp", frame);
}

} // namespace slides
