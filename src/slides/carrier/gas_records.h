// GasRecords: the gas of one OpenFOAM time directory as one field of records (carrier/
// gas_values.h): U, and k, ε and T where the directory has them, each within its physical bound.
//
// Read for a frozen carrier (carrier/foam_carrier.h) and for each level of a time series
// (carrier/foam_series.h), so a sample loads four records of a level, not four values of each
// field from separate arrays.
//
//     0.5/U, 0.5/k, 0.5/epsilon  →  FoamVolField<GasValues> (T left zero)
#pragma once

#include "slides/carrier/foam_field.h"
#include "slides/carrier/gas_values.h"

#include <array>
#include <filesystem>

namespace slides {

/// The optional scalars, in the order of GasValues::scalars.
inline constexpr std::array<const char*, 3> gasScalarNames{"k", "epsilon", "T"};

/// Which of k, ε and T the time directory holds.
std::array<bool, 3> gasScalarsIn(const std::filesystem::path& timeDirectory);

/// U and the scalars marked in `scalars` (k, ε ≥ 0, T > 0: InputError naming the file otherwise)
/// as one field; a patch gets face values where any field has them, the others' taken from the
/// owner cell there, as PointWeights treats a patch without values (carrier/foam_interpolation.h).
FoamVolField<GasValues> readGasRecords(const std::filesystem::path& timeDirectory,
                                       const FoamMesh& mesh, const std::array<bool, 3>& scalars);

} // namespace slides
