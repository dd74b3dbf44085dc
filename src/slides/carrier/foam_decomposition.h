// FoamDecomposition: the processor*/ parts of a decomposed OpenFOAM case, as decomposePar
// writes them, and the checks that they fit the run.
//
// Reference: OpenFOAM v1912 User Guide 3.4 "Running applications in parallel": decomposePar
// writes CASE/processor<N>/constant/polyMesh and processor<N>/<time>/ fields, one folder a rank;
// `mpirun -np N solver -parallel` runs them; reconstructPar puts the parts back together.
//
//     mpirun -np 4 slides-track CASE -parallel     // reads CASE/processor<rank>/ on each rank
#pragma once

#include <filesystem>
#include <string>

namespace slides {

/// How many processor<N>/ folders CASE holds (processor0 … processor<N−1>, without gaps).
int foamProcessorCount(const std::filesystem::path& caseDirectory);

/// CASE/processor<rank>.
std::filesystem::path foamProcessorDirectory(const std::filesystem::path& caseDirectory, int rank);

/// InputError unless a run on `ranks` ranks (parallel: under -parallel) fits the case: a
/// parallel run needs one processor folder a rank, all holding the same time directories; a
/// serial run of a decomposed case needs the whole case beside the parts (its mesh, and the
/// processors' latest time). Each message says what to run instead.
void requireDecompositionFits(const std::filesystem::path& caseDirectory, bool parallel, int ranks);

} // namespace slides
