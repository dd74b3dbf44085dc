#include "slides/carrier/foam_field.h"

#include "slides/carrier/foam_file.h"
#include "slides/core/error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <regex>
#include <sstream>
#include <type_traits>

namespace slides {

namespace {

template <typename T> struct FieldTraits;
template <> struct FieldTraits<double> {
    static constexpr const char* className = "volScalarField";
    static constexpr const char* listType = "List<scalar>";
};
template <> struct FieldTraits<Vec3> {
    static constexpr const char* className = "volVectorField";
    static constexpr const char* listType = "List<vector>";
};

template <typename T> T element(FoamFile& in);
template <> double element<double>(FoamFile& in) { return in.scalar(); }
template <> Vec3 element<Vec3>(FoamFile& in) { return in.vector(); }

template <typename T> T zero();
template <> double zero<double>() { return 0.0; }
template <> Vec3 zero<Vec3>() { return Vec3::Zero(); }

/// `uniform v` or `nonuniform List<T> N (...)` of count values, then ';'.
template <typename T> std::vector<T> readValues(FoamFile& in, int count) {
    const std::string kind = in.word();
    std::vector<T> values;
    if (kind == "uniform") {
        values.assign(static_cast<std::size_t>(count), element<T>(in));
    } else if (kind == "nonuniform") {
        const std::string type = in.word();
        if (type == "0" && count == 0) { // decomposePar's empty patch part: `0()`, binary `0`
            if (in.peek() == '(') {
                in.expect('(');
                in.expect(')');
            }
            in.expect(';');
            return values;
        }
        if (type != FieldTraits<T>::listType)
            in.fail("expected " + std::string(FieldTraits<T>::listType) + ", found '" + type + "'");
        values = in.list<T>(count);
    } else {
        in.fail("bad token '" + kind + "': expected uniform or nonuniform");
    }
    in.expect(';');
    return values;
}

/// The dimension set [kg m s K mol A cd] a field of this name must have, and what it is.
struct KnownDimensions {
    const char* field;
    std::array<double, 7> exponents;
    const char* quantity;
};
constexpr std::array<KnownDimensions, 4> knownDimensions{{
    {"U", {0, 1, -1, 0, 0, 0, 0}, "a velocity"},
    {"k", {0, 2, -2, 0, 0, 0, 0}, "a turbulent kinetic energy"},
    {"epsilon", {0, 2, -3, 0, 0, 0, 0}, "a dissipation rate"},
    {"T", {0, 0, 0, 1, 0, 0, 0}, "a temperature"},
}};

std::string dimensionText(const std::vector<double>& exponents) {
    std::ostringstream out;
    out << "[";
    for (std::size_t i = 0; i < exponents.size(); ++i) out << (i ? " " : "") << exponents[i];
    out << "]";
    return out.str();
}

/// `[e1 ... e7];` (or 5 exponents) after the keyword dimensions, checked against the field's
/// known dimension set.
void readDimensions(FoamFile& in, const KnownDimensions* known) {
    in.expect('[');
    std::vector<double> exponents;
    while (in.peek() != ']' && exponents.size() < 8) exponents.push_back(in.scalar());
    in.expect(']');
    in.expect(';');
    if (!known) return;
    std::vector<double> expected(known->exponents.begin(), known->exponents.end());
    std::vector<double> padded = exponents;
    if (padded.size() == 5) padded.resize(7, 0.0);
    if (padded != expected)
        throw InputError(in.name(), in.line(), "dimensions",
                         dimensionText(exponents) + " are not the dimensions of " + known->field +
                             ", " + known->quantity + " " + dimensionText(expected));
}

/// The argument of a #include-like directive (a quoted path or a word).
void skipDirectiveArgument(FoamFile& in) {
    if (in.peek() == '"')
        in.quoted();
    else
        in.word();
}

} // namespace

template <typename T>
FoamVolField<T> readFoamVolField(const std::filesystem::path& timeDirectory,
                                 const std::string& name, const FoamMesh& mesh) {
    // A value is at most ~80 characters in ASCII (a vector of three 17-digit numbers); a
    // boundary patch may hold a few lists of face values (value, inletValue, ...).
    const std::size_t boundaryFaces =
        static_cast<std::size_t>(mesh.faceCount() - mesh.internalFaceCount());
    const std::size_t maxBytes =
        (std::size_t{1} << 20) +
        128 * (static_cast<std::size_t>(mesh.cellCount) + 4 * boundaryFaces);
    FoamFile in(timeDirectory / name, maxBytes,
                "more than a field of " + std::to_string(mesh.cellCount) + " cells and " +
                    std::to_string(boundaryFaces) + " boundary faces can hold");
    const auto known = std::find_if(knownDimensions.begin(), knownDimensions.end(),
                                    [&](const KnownDimensions& k) { return name == k.field; });
    const KnownDimensions* dimensions = known == knownDimensions.end() ? nullptr : &*known;
    bool hasDimensions = false;
    FoamVolField<T> field;
    field.file = in.name();
    if (in.className() != FieldTraits<T>::className)
        in.fail("class " + in.className() + ", expected " + FieldTraits<T>::className);
    field.patchValues.resize(mesh.patches.size());
    bool hasInternal = false;
    std::vector<bool> covered(mesh.patches.size(), false);
    bool constraintTypesSet = false;
    int boundaryLine = 0; ///< 0 while the file has no boundaryField
    while (!in.atEnd()) {
        const std::string key = in.word();
        if (key[0] == '#') {
            skipDirectiveArgument(in);
        } else if (key == "dimensions") {
            readDimensions(in, dimensions);
            hasDimensions = true;
        } else if (key == "internalField") {
            field.cells = readValues<T>(in, mesh.cellCount);
            hasInternal = true;
        } else if (key == "boundaryField") {
            boundaryLine = in.line();
            in.expect('{');
            while (in.peek() != '}') {
                // A patch by name, or a quoted regular expression for the patches without a
                // value yet (OpenFOAM: an exact name wins over a pattern).
                const bool pattern = in.peek() == '"';
                const std::string name = pattern ? in.quoted() : in.word();
                if (name[0] == '#') { // #includeEtc "caseDicts/setConstraintTypes": no values
                    skipDirectiveArgument(in);
                    constraintTypesSet = true;
                    continue;
                }
                const std::regex expression(pattern ? name : std::string("^$"));
                std::vector<std::size_t> patches;
                for (std::size_t p = 0; p < mesh.patches.size(); ++p)
                    if (pattern ? std::regex_match(mesh.patches[p].name, expression) &&
                                      field.patchValues[p].empty()
                                : mesh.patches[p].name == name)
                        patches.push_back(p);
                for (const std::size_t p : patches) covered[p] = true;
                in.expect('{');
                while (in.peek() != '}') {
                    const std::string entry = in.word();
                    if (entry == "type" && in.peek() != '"') {
                        // noSlip (a wall at rest) writes no value: its value is zero.
                        const std::string type = in.word();
                        in.expect(';');
                        for (const std::size_t p : patches)
                            if (type == "noSlip" && field.patchValues[p].empty())
                                field.patchValues[p].assign(mesh.patches[p].size, zero<T>());
                    } else if (entry == "value" && !patches.empty()) {
                        const auto values = readValues<T>(in, mesh.patches[patches[0]].size);
                        for (const std::size_t p : patches)
                            field.patchValues[p] =
                                values.size() == static_cast<std::size_t>(mesh.patches[p].size)
                                    ? values
                                    : std::vector<T>(mesh.patches[p].size, values.at(0));
                    } else {
                        in.skipValue();
                    }
                }
                in.expect('}');
            }
            in.expect('}');
        } else {
            in.skipValue();
        }
    }
    if (!hasInternal) in.fail("no internalField");
    if (dimensions && !hasDimensions)
        throw InputError(
            field.file, 0, "dimensions",
            std::string("missing; ") + dimensions->field + " is " + dimensions->quantity + " " +
                dimensionText({dimensions->exponents.begin(), dimensions->exponents.end()}));
    requireFinite(field, mesh);
    for (std::size_t p = 0; p < mesh.patches.size(); ++p) {
        // #includeEtc "caseDicts/setConstraintTypes" sets the constraint patches' types.
        const bool constraint = mesh.patches[p].type == PatchType::empty ||
                                mesh.patches[p].type == PatchType::wedge ||
                                mesh.patches[p].type == PatchType::symmetry;
        if (!covered[p] && !(constraint && constraintTypesSet))
            throw InputError(field.file, boundaryLine, "boundaryField",
                             "no entry for patch '" + mesh.patches[p].name + "' of the mesh");
    }
    return field;
}

namespace {

bool isFinite(double value) { return std::isfinite(value); }
bool isFinite(const Vec3& value) { return value.allFinite(); }

template <typename T> std::string text(const T& value) {
    std::ostringstream out;
    if constexpr (std::is_same_v<T, double>)
        out << value;
    else
        out << "(" << value.transpose() << ")";
    return out.str();
}

} // namespace

template <typename T> void requireFinite(const FoamVolField<T>& field, const FoamMesh& mesh) {
    for (std::size_t cell = 0; cell < field.cells.size(); ++cell)
        if (!isFinite(field.cells[cell]))
            throw InputError(field.file, 0, "",
                             "cell " + std::to_string(cell) + " of internalField holds " +
                                 text(field.cells[cell]) + ", not a finite value");
    for (std::size_t patch = 0; patch < field.patchValues.size(); ++patch)
        for (std::size_t face = 0; face < field.patchValues[patch].size(); ++face)
            if (!isFinite(field.patchValues[patch][face]))
                throw InputError(field.file, 0, "",
                                 "face " + std::to_string(face) + " of patch " +
                                     mesh.patches[patch].name + " holds " +
                                     text(field.patchValues[patch][face]) + ", not a finite value");
}

template void requireFinite<double>(const FoamVolField<double>&, const FoamMesh&);
template void requireFinite<Vec3>(const FoamVolField<Vec3>&, const FoamMesh&);

void requireAtLeast(const FoamVolField<double>& field, double minimum, bool inclusive,
                    const std::string& quantity) {
    for (std::size_t cell = 0; cell < field.cells.size(); ++cell) {
        const double value = field.cells[cell];
        if (inclusive ? value >= minimum : value > minimum) continue;
        throw InputError(field.file, 0, "",
                         "cell " + std::to_string(cell) + " has " + quantity + " = " + text(value) +
                             ", which must be " + (inclusive ? "at least " : "above ") +
                             text(minimum));
    }
}

template FoamVolField<double> readFoamVolField<double>(const std::filesystem::path&,
                                                       const std::string&, const FoamMesh&);
template FoamVolField<Vec3> readFoamVolField<Vec3>(const std::filesystem::path&, const std::string&,
                                                   const FoamMesh&);

std::filesystem::path foamTimeDirectory(const std::filesystem::path& caseDirectory,
                                        const std::string& time) {
    const bool latest = time == "latestTime";
    char* end = nullptr;
    const double wanted = latest ? 0.0 : std::strtod(time.c_str(), &end);
    if (!latest && (end == time.c_str() || *end))
        throw InputError(caseDirectory.string(), 0, "time",
                         "'" + time + "' is neither latestTime nor a time value");
    std::optional<std::filesystem::path> best;
    double bestTime = -INFINITY;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(caseDirectory, error)) {
        if (!entry.is_directory()) continue;
        const std::string name = entry.path().filename().string();
        const double value = std::strtod(name.c_str(), &end);
        if (end == name.c_str() || *end) continue;
        if (latest && value > bestTime && FoamFile::exists(entry.path() / "U")) {
            best = entry.path();
            bestTime = value;
        }
        if (!latest && std::abs(value - wanted) <= 1e-12 * std::max(1.0, std::abs(wanted)))
            best = entry.path();
    }
    if (!best)
        throw InputError(caseDirectory.string(), 0, "time",
                         latest ? "no time directory holds a field U (run the case's Allrun first)"
                                : "no time directory " + time);
    return *best;
}

} // namespace slides
