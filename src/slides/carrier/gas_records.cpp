#include "slides/carrier/gas_records.h"

#include "slides/carrier/foam_file.h"

#include <optional>

namespace slides {

std::array<bool, 3> gasScalarsIn(const std::filesystem::path& timeDirectory) {
    std::array<bool, 3> present{};
    for (int s = 0; s < 3; ++s) present[s] = FoamFile::exists(timeDirectory / gasScalarNames[s]);
    return present;
}

FoamVolField<GasValues> readGasRecords(const std::filesystem::path& timeDirectory,
                                       const FoamMesh& mesh, const std::array<bool, 3>& scalars) {
    const auto velocity = readFoamVolField<Vec3>(timeDirectory, "U", mesh);
    std::array<std::optional<FoamVolField<double>>, 3> read;
    for (int s = 0; s < 3; ++s) {
        if (!scalars[s]) continue;
        read[s] = readFoamVolField<double>(timeDirectory, gasScalarNames[s], mesh);
        requireAtLeast(*read[s], 0, s < 2, gasScalarNames[s]);
    }
    FoamVolField<GasValues> gas;
    gas.file = velocity.file;
    gas.cells.resize(velocity.cells.size());
    for (std::size_t c = 0; c < gas.cells.size(); ++c) {
        gas.cells[c].velocity = velocity.cells[c];
        for (int s = 0; s < 3; ++s)
            if (read[s]) gas.cells[c].scalars[s] = read[s]->cells[c];
    }
    gas.patchValues.resize(mesh.patches.size());
    for (std::size_t p = 0; p < mesh.patches.size(); ++p) {
        const auto given = [&](const auto& field) { return !field.patchValues[p].empty(); };
        bool any = given(velocity);
        for (const auto& scalar : read) any = any || (scalar && given(*scalar));
        if (!any) continue;
        const int start = mesh.patches[p].start;
        for (int f = 0; f < mesh.patches[p].size; ++f) {
            GasValues face = gas.cells[mesh.owner[start + f]];
            if (given(velocity)) face.velocity = velocity.patchValues[p][f];
            for (int s = 0; s < 3; ++s)
                if (read[s] && given(*read[s])) face.scalars[s] = read[s]->patchValues[p][f];
            gas.patchValues[p].push_back(face);
        }
    }
    return gas;
}

} // namespace slides
