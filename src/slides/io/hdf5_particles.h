// ParticlesHdf5: every particle frame of a run, and its arrivals, in one HDF5 file, with an
// XDMF index (io/xdmf_particles.h) so ParaView opens it directly (Xdmf reader).
//
//     output { hdf5 yes; }   // particles.h5 + particles.xmf beside the .vtp frames
//
// Layout of particles.h5; every dataset has a `units` attribute (SI, "1" for pure numbers):
//   /                    software, version, case (attributes); frames (count, at the end)
//   /frames/NNNNNN       one group per frame, attribute time [s]; the arrays of the frame's
//                        field set (output.fields), one row per particle, moving ones first:
//       id         uint64 (N)      stable particle id
//       position   float64 (N, 3)  centre [m] (always written: the XDMF geometry)
//       velocity   float64 (N, 3)  [m/s]
//       diameter   float64 (N)     [m]
//       speed      float64 (N)     [m/s]
//       state      int32 (N)       0 moving, 1 arrived (frozen where it touched)
//       temperature float64 (N)    [K], with heat transfer
//       angularVelocity float64 (N, 3) [rad/s], where the particles spin (scene.h tracksSpin)
//       charge     float64 (N)    [C], with electromagnetic forces (physics/electromagnetic.h)
//       injector   int32 (N)       index of the injector in `injectors {}`, with several
//       density    float64 (N)     [kg/m³], where the particles differ (species of injectors or
//                                  of a file's rows)
//   /arrivals            written when the run ends, one row per particle that reached a
//                        surface: id, surface (index into the case's surfaces), time [s],
//                        position [m], velocity [m/s], diameter [m], and density [kg/m³] where
//                        the particles differ
// Datasets are chunked, shuffled and deflate-compressed. During the run the file is
// `particles.h5.partial`, flushed after every frame, so a run stopped early keeps its frames
// under a name that says it is incomplete; finish() renames it to particles.h5 and then
// writes particles.xmf.
#pragma once

#include "slides/io/frame_record.h"
#include "slides/io/hdf5_file.h"
#include "slides/io/vtk_particles.h"
#include "slides/io/xdmf_particles.h"
#include "slides/surfaces/arrival.h"

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace slides {

/// The group of frame index in particles.h5: "/frames/000003".
std::string particlesFrameGroup(std::size_t index);

class ParticlesHdf5 {
public:
    /// Starts directory/particles.h5.partial; caseName is stored as an attribute.
    ParticlesHdf5(const std::filesystem::path& directory, const std::string& caseName);

    void writeFrame(double time, const ParticleFrame& frame);
    /// Writes /arrivals (with each one's density, if given), closes the file, renames it to
    /// particles.h5, writes particles.xmf.
    void finish(std::span<const Arrival> arrivals,
                std::optional<std::span<const double>> density = std::nullopt);

    static constexpr const char* fileName = "particles.h5";
    static constexpr const char* indexName = "particles.xmf";

private:
    std::filesystem::path directory_;
    std::optional<Hdf5File> file_;
    std::vector<XdmfFrame> frames_;
    std::vector<double> scratch_;
};

} // namespace slides
