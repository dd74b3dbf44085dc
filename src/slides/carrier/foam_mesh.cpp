#include "slides/carrier/foam_mesh.h"

#include "slides/carrier/foam_file.h"
#include "slides/core/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace slides {

namespace {

PatchType patchTypeNamed(const std::string& type) {
    if (type == "wall") return PatchType::wall;
    if (type == "symmetry" || type == "symmetryPlane") return PatchType::symmetry;
    if (type == "wedge") return PatchType::wedge;
    if (type == "empty") return PatchType::empty;
    if (type == "processor") return PatchType::processor;
    return PatchType::patch; // patch and the rest (mapped, cyclic, ...) bound the domain alike
}

std::vector<FoamPatch> readBoundary(const std::filesystem::path& file) {
    FoamFile in(file);
    std::vector<FoamPatch> patches(static_cast<std::size_t>(in.label()));
    in.expect('(');
    for (FoamPatch& patch : patches) {
        patch.name = in.word();
        in.expect('{');
        bool hasSize = false, hasStart = false;
        while (in.peek() != '}') {
            const std::string key = in.word();
            if (key == "type") {
                patch.type = patchTypeNamed(in.word());
            } else if (key == "nFaces") {
                patch.size = static_cast<int>(in.label());
                hasSize = true;
            } else if (key == "startFace") {
                patch.start = static_cast<int>(in.label());
                hasStart = true;
            } else if (key == "neighbProcNo") {
                patch.neighbourRank = static_cast<int>(in.label());
            } else {
                in.skipValue();
                continue;
            }
            in.expect(';');
        }
        in.expect('}');
        if (!hasSize || !hasStart) in.fail("patch " + patch.name + " lacks nFaces or startFace");
        if (patch.type == PatchType::processor && patch.neighbourRank < 0)
            in.fail("processor patch " + patch.name + " lacks neighbProcNo");
    }
    in.expect(')');
    return patches;
}

/// Labels as int (meshes here have fewer than 2³¹ points, faces and cells); one beyond that
/// range is an error of the file, not a silent wrap-around.
std::vector<int> toInt(const std::vector<std::int64_t>& values, const FoamFile& in) {
    for (const auto value : values)
        if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max())
            in.fail("label " + std::to_string(value) + " out of range");
    return {values.begin(), values.end()};
}

/// InputError when a cell is inverted or tangled: a tetrahedron of the decomposition the
/// locator walks (cell centre, face point-average, two consecutive face points) with negative
/// volume, beyond round-off of the cell's volume. A point in such a cell is found in no cell, or
/// in two, and interpolation weights there are meaningless.
void requireUntangledCells(const FoamMesh& mesh, const std::filesystem::path& directory) {
    for (int c = 0; c < mesh.cellCount; ++c) {
        const double roundOff = 1e-10 * std::abs(mesh.cellVolumes[c]);
        for (const int f : mesh.facesOf(c)) {
            const auto ring = mesh.pointsOf(f);
            Vec3 midpoint = Vec3::Zero();
            for (const int p : ring) midpoint += mesh.points[p];
            midpoint /= static_cast<double>(ring.size());
            const double outward = mesh.owner[f] == c ? 1.0 : -1.0;
            for (std::size_t e = 0; e < ring.size(); ++e) {
                const Vec3& a = mesh.points[ring[e]];
                const Vec3& b = mesh.points[ring[(e + 1) % ring.size()]];
                const double volume =
                    outward *
                    (midpoint - mesh.cellCentres[c]).dot((a - midpoint).cross(b - midpoint)) / 6;
                if (mesh.cellVolumes[c] > 0 && volume >= -roundOff) continue;
                std::ostringstream what;
                what << "cell " << c << " is inverted or tangled: volume " << mesh.cellVolumes[c]
                     << " m³, its tetrahedron on face " << f << " has volume " << volume << " m³";
                throw InputError(directory.string(), 0, "", what.str());
            }
        }
    }
}

} // namespace

std::vector<FoamPatch> readFoamBoundary(const std::filesystem::path& caseDirectory) {
    const auto whole = caseDirectory / "constant" / "polyMesh" / "boundary";
    const auto part = caseDirectory / "processor0" / "constant" / "polyMesh" / "boundary";
    if (FoamFile::exists(whole) || !FoamFile::exists(part)) return readBoundary(whole);
    // A decomposed case: every part lists the case's patches, then its processor patches.
    std::vector<FoamPatch> patches = readBoundary(part);
    std::erase_if(patches, [](const FoamPatch& p) { return p.type == PatchType::processor; });
    return patches;
}

FoamMesh readFoamMesh(const std::filesystem::path& caseDirectory) {
    const auto dir = caseDirectory / "constant" / "polyMesh";
    FoamMesh mesh;
    {
        FoamFile in(dir / "points");
        mesh.points = in.list<Vec3>();
        for (std::size_t p = 0; p < mesh.points.size(); ++p)
            if (!mesh.points[p].allFinite())
                in.fail("point " + std::to_string(p) + " is not finite");
    }
    {
        FoamFile in(dir / "faces");
        std::vector<std::int64_t> offsets, labels;
        in.faces(offsets, labels);
        for (const auto point : labels)
            if (point < 0 || point >= static_cast<std::int64_t>(mesh.points.size()))
                in.fail("face point label " + std::to_string(point) + " outside the " +
                        std::to_string(mesh.points.size()) + " points");
        mesh.faceOffsets = toInt(offsets, in);
        mesh.facePoints = toInt(labels, in);
    }
    const long faceCount = static_cast<long>(mesh.faceOffsets.size()) - 1;
    {
        FoamFile in(dir / "owner");
        mesh.owner = toInt(in.list<std::int64_t>(faceCount), in);
    }
    {
        FoamFile in(dir / "neighbour");
        mesh.neighbour = toInt(in.list<std::int64_t>(), in);
        if (static_cast<long>(mesh.neighbour.size()) > faceCount)
            in.fail("more neighbours than faces");
    }
    mesh.patches = readBoundary(dir / "boundary");
    // Every cell has at least 4 faces and a face at most 2 cells: at most faceCount / 2 cells.
    const auto checkCells = [&](const std::vector<int>& cells, const char* file) {
        for (const int cell : cells)
            if (cell < 0 || cell > faceCount / 2)
                throw InputError((dir / file).string(), 0, "",
                                 "cell label " + std::to_string(cell) +
                                     " impossible for a mesh of " + std::to_string(faceCount) +
                                     " faces");
    };
    checkCells(mesh.owner, "owner");
    checkCells(mesh.neighbour, "neighbour");
    mesh.cellCount = 0;
    for (const int cell : mesh.owner) mesh.cellCount = std::max(mesh.cellCount, cell + 1);
    for (const int cell : mesh.neighbour) mesh.cellCount = std::max(mesh.cellCount, cell + 1);
    int expectedStart = mesh.internalFaceCount();
    for (const auto& patch : mesh.patches) {
        if (patch.start != expectedStart || patch.size < 0)
            throw InputError((dir / "boundary").string(), 0, patch.name,
                             "startFace " + std::to_string(patch.start) + " should be " +
                                 std::to_string(expectedStart));
        expectedStart += patch.size;
    }
    if (expectedStart != faceCount)
        throw InputError((dir / "boundary").string(), 0, "",
                         "patches end at face " + std::to_string(expectedStart) +
                             " but the mesh has " + std::to_string(faceCount) + " faces");
    mesh.computeGeometry();
    requireUntangledCells(mesh, dir);
    return mesh;
}

void FoamMesh::computeGeometry() {
    const int faces = faceCount();
    faceCentres.assign(faces, Vec3::Zero());
    faceAreas.assign(faces, Vec3::Zero());
    for (int f = 0; f < faces; ++f) { // primitiveMeshFaceCentresAndAreas.C
        const auto ring = pointsOf(f);
        const std::size_t n = ring.size();
        if (n == 3) {
            const Vec3 &a = points[ring[0]], &b = points[ring[1]], &c = points[ring[2]];
            faceCentres[f] = (a + b + c) / 3;
            faceAreas[f] = 0.5 * (b - a).cross(c - a);
            continue;
        }
        Vec3 estimate = Vec3::Zero();
        for (const int p : ring) estimate += points[p];
        estimate /= static_cast<double>(n);
        Vec3 sumN = Vec3::Zero(), sumAc = Vec3::Zero();
        double sumA = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const Vec3& here = points[ring[i]];
            const Vec3& next = points[ring[(i + 1) % n]];
            const Vec3 normal = (next - here).cross(estimate - here);
            const double area = normal.norm();
            sumN += normal;
            sumA += area;
            sumAc += area * (here + next + estimate);
        }
        faceCentres[f] = sumA > 1e-300 ? Vec3(sumAc / (3 * sumA)) : estimate;
        faceAreas[f] = 0.5 * sumN;
    }

    std::vector<int> count(cellCount + 1, 0);
    for (int f = 0; f < faces; ++f) {
        ++count[owner[f] + 1];
        if (f < internalFaceCount()) ++count[neighbour[f] + 1];
    }
    cellFaceOffsets.assign(cellCount + 1, 0);
    for (int c = 0; c < cellCount; ++c) cellFaceOffsets[c + 1] = cellFaceOffsets[c] + count[c + 1];
    cellFaces.assign(cellFaceOffsets.back(), 0);
    std::vector<int> fill(cellFaceOffsets.begin(), cellFaceOffsets.end() - 1);
    for (int f = 0; f < faces; ++f) {
        cellFaces[fill[owner[f]]++] = f;
        if (f < internalFaceCount()) cellFaces[fill[neighbour[f]]++] = f;
    }

    // primitiveMeshCellCentresAndVols.C: pyramids on the faces about the face-centre average.
    cellCentres.assign(cellCount, Vec3::Zero());
    cellVolumes.assign(cellCount, 0.0);
    for (int c = 0; c < cellCount; ++c) {
        Vec3 estimate = Vec3::Zero();
        for (const int f : facesOf(c)) estimate += faceCentres[f];
        estimate /= static_cast<double>(facesOf(c).size());
        Vec3 moment = Vec3::Zero();
        double volume3 = 0;
        for (const int f : facesOf(c)) {
            const double sign = owner[f] == c ? 1.0 : -1.0;
            const double pyramid3 = sign * faceAreas[f].dot(faceCentres[f] - estimate);
            moment += pyramid3 * (0.75 * faceCentres[f] + 0.25 * estimate);
            volume3 += pyramid3;
        }
        cellCentres[c] = std::abs(volume3) > 1e-300 ? Vec3(moment / volume3) : estimate;
        cellVolumes[c] = volume3 / 3;
    }

    facePatch.assign(faces, -1);
    for (int p = 0; p < static_cast<int>(patches.size()); ++p)
        std::fill_n(facePatch.begin() + patches[p].start, patches[p].size, p);

    boundsMin = boundsMax = points.empty() ? Vec3::Zero() : points.front();
    for (const Vec3& point : points) {
        boundsMin = boundsMin.cwiseMin(point);
        boundsMax = boundsMax.cwiseMax(point);
    }
}

} // namespace slides
