// Case template: `slides-track --init CASE` writes a commented constant/slidesProperties that
// runs as written. The comment above each key is its declaration in the key table
// (config/scene_keys.h): doc line, unit, default and allowed names, so the template stays true
// as keys change.
//
// An OpenFOAM case (constant/polyMesh and a time directory with U) gets the foamField carrier,
// its patches in the surfaces section (wall patches as absorbing surfaces, the others as
// exits), the carrier's box as the domain and the particles entering through its inlet
// (carrier/foam_case_outline.h); a directory that is no OpenFOAM case gets the analytic sech²
// jet of foamCases/analyticSpray (Eq. 5.10/5.11). An OpenFOAM case not meshed yet is refused.
//
//     slides-track --init myCase     # writes myCase/constant/slidesProperties, never over one
#pragma once

#include <filesystem>
#include <string>

namespace slides {

/// The dictionary text of the template for caseDirectory; InputError for a mesh or field the
/// run would refuse, or an OpenFOAM case (system/controlDict) without its mesh.
std::string caseTemplate(const std::filesystem::path& caseDirectory);

/// Writes caseTemplate(caseDirectory) to caseDirectory/constant/slidesProperties (atomically)
/// and returns that path. InputError, nothing written, when caseDirectory is not a directory or
/// the dictionary exists already.
std::filesystem::path writeCaseTemplate(const std::filesystem::path& caseDirectory);

} // namespace slides
