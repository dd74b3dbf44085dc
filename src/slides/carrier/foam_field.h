// FoamVolField: an OpenFOAM volScalarField or volVectorField of one time directory.
//
// Reference: OpenFOAM v1912 field file format (User Guide 4.2 "Data files"): `internalField
// uniform v;` or `nonuniform List<T> N (...)`, and per patch of `boundaryField` its `value`
// entry when the patch type writes one (fixedValue, calculated, inletOutlet, ...); noSlip
// (no value written) is zero; other patches without a value (zeroGradient, empty, wedge,
// symmetry) have none here.
//
//     0.5/U[.gz]:  internalField nonuniform List<vector> 1200 ( ... );
//                  boundaryField { inlet { type fixedValue; value uniform (0 0 10); } }
#pragma once

#include "slides/carrier/foam_mesh.h"

#include <filesystem>
#include <string>
#include <vector>

namespace slides {

template <typename T> struct FoamVolField {
    std::string file;
    std::vector<T> cells;                    ///< one value per cell
    std::vector<std::vector<T>> patchValues; ///< per mesh patch: its face values, or empty
};

/// Reads CASE/timeDirectory/name for mesh; InputError naming the file when it is missing, of
/// the wrong class, has a bad token, or a list whose size does not match the mesh.
template <typename T>
FoamVolField<T> readFoamVolField(const std::filesystem::path& timeDirectory,
                                 const std::string& name, const FoamMesh& mesh);

/// InputError naming the field's file and the first cell (or patch face) whose value is not
/// finite: NaN or infinity from a diverged solution must not reach the particles.
template <typename T> void requireFinite(const FoamVolField<T>& field, const FoamMesh& mesh);

/// InputError naming the file and the first cell whose value is below minimum (k, ε ≥ 0,
/// T > 0 are physical bounds a diverged or badly initialised field breaks).
void requireAtLeast(const FoamVolField<double>& field, double minimum, bool inclusive,
                    const std::string& quantity);

/// The time directory of caseDirectory named by time: "latestTime" (the largest numeric
/// directory holding U), or a time value such as "0.5" (compared as numbers, like `-time`).
std::filesystem::path foamTimeDirectory(const std::filesystem::path& caseDirectory,
                                        const std::string& time);

} // namespace slides
