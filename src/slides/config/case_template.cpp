#include "slides/config/case_template.h"

#include "slides/carrier/foam_case_outline.h"
#include "slides/config/commented_dictionary.h"
#include "slides/config/dictionary.h"
#include "slides/core/error.h"
#include "slides/io/atomic_file.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace slides {

namespace {

namespace fs = std::filesystem;

// The particles of every template: a metal powder as sprayed, 1000 particles of 10 µm.
constexpr int particleCount = 1000;
constexpr double particleDensity = 7900; // kg/m³, stainless steel
constexpr double particleRadius = 5e-6;  // m
// Air at 20 °C where the case does not say (an incompressible solution carries no density).
constexpr double airDensity = 1.2;               // kg/m³
constexpr double airKinematicViscosity = 1.5e-5; // m²/s
// Particles are injected over one transit of the gas through the domain (its largest extent
// over the inflow speed) and tracked for ten; the run stops earlier when all are done.
constexpr double transitsInjected = 1;
constexpr double transitsTracked = 10;
constexpr int framesPerRun = 50;
// The domain box exceeds the carrier's by this share of its largest extent on every side, so
// that a nozzle on the mesh's boundary lies inside it; the mesh's patches bound the run first.
constexpr double domainMargin = 0.01;

std::string number(double value, int significantDigits = 9) {
    std::ostringstream text;
    text << std::setprecision(significantDigits) << value;
    return text.str();
}

/// value to two significant digits, as a person would write a time.
double rounded(double value) { return std::stod(number(value, 2)); }

/// (x y z), components below 1e-9 of scale (round-off of the mesh's geometry) written as 0.
std::string vectorText(const Vec3& v, double scale = 1) {
    const auto clean = [&](double c) { return std::abs(c) < 1e-9 * scale ? 0.0 : c; };
    std::ostringstream text;
    text << std::setprecision(9) << "(" << clean(v.x()) << " " << clean(v.y()) << " "
         << clean(v.z()) << ")";
    return text.str();
}

std::string header(const std::string& about) {
    return "/*--------------------------------*- C++ -*----------------------------------*\\\n"
           "  SLIDES-track case dictionary written by `slides-track --init`: " +
           about +
           "\n  It runs as written; edit it to your spray. Check it without running:\n"
           "  `slides-track CASE --check`. Every key, unit and default: README.md or\n"
           "  `slides-track --list-keys`.\n"
           "\\*---------------------------------------------------------------------------*/\n"
           "FoamFile\n{\n    version     2.0;\n    format      ascii;\n"
           "    class       dictionary;\n    location    \"constant\";\n"
           "    object      slidesProperties;\n}\n"
           "// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //\n\n";
}

const char* footer =
    "// ************************************************************************* //\n";

void fluid(CommentedDictionary& text, double kinematicViscosity,
           const std::string& viscositySource) {
    text.open("fluid");
    text.entry("density", number(airDensity), "air at 20 °C");
    text.entry("kinematicViscosity", number(kinematicViscosity), viscositySource);
    text.close();
}

void particles(CommentedDictionary& text, bool countHere) {
    text.open("particles");
    if (countHere) text.entry("count", std::to_string(particleCount));
    text.entry("density", number(particleDensity),
               "stainless steel powder; aluminium 2700, copper 8960");
    text.open("radiusDistribution");
    text.entry("type", "fixed");
    text.entry("value", number(particleRadius), "10 µm diameter");
    text.close();
    text.close();
}

/// The nozzle disc and its injection at rate, over injectionTime; lengthScale: the scene's size.
void nozzleInjection(CommentedDictionary& text, const Vec3& centre, const Vec3& axis, double radius,
                     const Vec3& crossSpanDirection, double injectionTime, double lengthScale,
                     const std::string& where) {
    text.open("nozzle");
    text.note(where);
    text.entry("centre", vectorText(centre, lengthScale));
    text.entry("axis", vectorText(axis));
    text.entry("radius", number(radius));
    text.entry("crossSpanDirection", vectorText(crossSpanDirection));
    text.close();
    text.open("injection");
    text.entry("mode", "rate");
    text.entry("rate", number(particleCount / injectionTime),
               "all " + std::to_string(particleCount) + " within " + number(injectionTime) + " s");
    text.defaultEntry("crossSpanSpeed");
    text.defaultEntry("seed");
    text.close();
}

void physics(CommentedDictionary& text, const std::string& gravity,
             const std::string& gravityNote) {
    text.open("physics");
    text.defaultEntry("drag");
    text.entry("gravity", gravity, gravityNote);
    text.close();
}

void time(CommentedDictionary& text, double endTime) {
    text.open("time");
    text.commentedEntry("dt", "1e-5");
    text.entry("endTime", number(endTime));
    text.defaultEntry("stopWhenAllDone");
    text.defaultEntry("integrator");
    text.close();
}

void domain(CommentedDictionary& text, const Box& box, const std::string& about) {
    text.open("domain");
    text.note(about);
    text.entry("min", vectorText(box.min));
    text.entry("max", vectorText(box.max));
    text.close();
}

void output(CommentedDictionary& text, double endTime) {
    text.open("output");
    text.entry("interval", number(endTime / framesPerRun),
               std::to_string(framesPerRun) + " frames to time.endTime");
    text.close();
}

/// The kinematic viscosity nu of constant/transportProperties, or air's; and where it came from.
std::pair<double, std::string> caseViscosity(const fs::path& caseDirectory) {
    const fs::path file = caseDirectory / "constant" / "transportProperties";
    if (fs::exists(file)) {
        const Dictionary transport = Dictionary::parseFile(file);
        if (transport.has("nu"))
            return {transport.scalar("nu"), "nu of constant/transportProperties"};
    }
    return {airKinematicViscosity, "air at 20 °C"};
}

/// A surface for each wall patch the run can meet; the other patches as comments.
void surfaces(CommentedDictionary& text, const FoamCaseOutline& outline) {
    const double lengthScale = (outline.bounds.max - outline.bounds.min).maxCoeff();
    text.open("surfaces");
    text.note("Every patch of constant/polyMesh/boundary. A particle leaving the mesh through a "
              "patch that is not a surface here escapes, counted under the patch's name in "
              "summary.json (escapedThrough).");
    for (const FoamPatchOutline& patch : outline.patches) {
        const std::string name = patch.name + " (" + patchTypeWord(patch.type) + "): ";
        const bool isInlet = outline.inlet && outline.inlet->name == patch.name;
        if (patch.type == PatchType::wall && outline.shape == FoamMeshShape::threeDimensional) {
            text.note(name + "met as the mesh's faces.");
            text.open(patch.name);
            text.entry("type", "patch");
            text.entry("patch", patch.name);
            text.defaultEntry("interaction");
            text.close();
        } else if (patch.type == PatchType::wall && patch.planar) {
            text.note(name + "met as its plane.");
            text.open(patch.name);
            text.entry("type", "plane");
            text.entry("point", vectorText(patch.point, lengthScale));
            text.entry("normal", vectorText(patch.inwardNormal));
            text.defaultEntry("interaction");
            text.close();
        } else if (patch.type == PatchType::wall) {
            text.note(name + "a wall of a wedge or 2-D mesh that is not one plane (across a "
                             "wedge's axis; a patch surface needs a 3-D mesh): an exit.");
        } else if (isInlet) {
            text.note(name + "the inlet the particles enter through; an exit like the others.");
        } else if (patch.type == PatchType::wedge) {
            text.note(name + "a side of the axisymmetric wedge: particles move in 3-D about its "
                             "axis and never meet it.");
        } else if (patch.type == PatchType::empty) {
            text.note(name + (outline.shape == FoamMeshShape::twoDimensional
                                  ? "a face of the 2-D mesh: particles move in its plane."
                                  : "a patch without faces here (a wedge's axis)."));
        } else {
            text.note(name + "an exit.");
        }
    }
    text.close();
}

/// Whether the particles enter by a patch injector on the inlet: on a 3-D mesh, and on a wedge
/// (over the surface the patch sweeps about the axis); a 2-D mesh's inlet gets a nozzle disc.
bool injectsOnInletPatch(const FoamCaseOutline& outline) {
    return outline.inlet && outline.shape != FoamMeshShape::twoDimensional;
}

/// The particles entering through the inlet: a patch injector on a 3-D or wedge mesh, a nozzle
/// disc on a 2-D mesh (carrier/foam_case_outline.h); without an inlet, a small disc at the
/// centre of the box. speed: the inflow's [m/s].
void inletInjection(CommentedDictionary& text, const FoamCaseOutline& outline, double injectionTime,
                    double speed) {
    const Vec3 extent = outline.bounds.max - outline.bounds.min;
    if (injectsOnInletPatch(outline)) {
        const std::string& inlet = outline.inlet->name;
        text.open("injectors");
        text.note("Particles enter through the inlet patch '" + inlet + "' (mean inflow " +
                  number(speed, 3) + " m/s)" +
                  (outline.shape == FoamMeshShape::wedge
                       ? ", over the surface it sweeps about the wedge's axis"
                       : "") +
                  ". Alternatives: a nozzle disc (model disc), a cone, "
                  "a file of particles: README.md, \"Injection\".");
        text.open(inlet);
        text.entry("model", "patch");
        text.open("patchCoeffs");
        text.entry("patch", inlet);
        text.close();
        text.entry("count", std::to_string(particleCount));
        text.entry("duration", number(injectionTime));
        text.close();
        text.close();
    } else if (outline.inlet) {
        const FoamInletOutline& inlet = *outline.inlet;
        nozzleInjection(text, inlet.centre, inlet.axis, inlet.radius, inlet.crossSpanDirection,
                        injectionTime, extent.maxCoeff(),
                        "On the inlet patch '" + inlet.name + "' (mean inflow " + number(speed, 3) +
                            " m/s): its centre" + ", its inward normal, its extent across it.");
    } else {
        const Vec3 centre = 0.5 * (outline.bounds.min + outline.bounds.max);
        nozzleInjection(text, centre, Vec3::UnitX(), 0.01 * extent.maxCoeff(), Vec3::UnitY(),
                        injectionTime, extent.maxCoeff(),
                        "No inlet patch found (none named inlet, none with inflow): a small "
                        "disc at the centre of the mesh's box. Move it to where particles enter.");
    }
}

std::string foamTemplate(const fs::path& caseDirectory) {
    const FoamCaseOutline outline = outlineFoamCase(caseDirectory);
    const char* shapes[] = {"3-D", "axisymmetric wedge", "2-D"};
    const std::string shape = shapes[static_cast<int>(outline.shape)];
    CommentedDictionary text;
    text.raw(header("the OpenFOAM case's\n  " + shape + " mesh and its U at time " + outline.time +
                    ", " + std::to_string(outline.patches.size()) + " patches."));

    const auto [viscosity, viscositySource] = caseViscosity(caseDirectory);
    fluid(text, viscosity, viscositySource);

    text.open("carrier");
    text.entry("type", "foamField");
    text.open("foamFieldCoeffs");
    text.entry("time", "latestTime", "now " + outline.time);
    text.defaultEntry("interpolation");
    text.close();
    text.close();

    const Vec3 extent = outline.bounds.max - outline.bounds.min;
    const double speed = outline.inlet && outline.inlet->inflowSpeed > 0
                             ? outline.inlet->inflowSpeed
                             : std::max(outline.largestSpeed, 1.0);
    const double transit = extent.maxCoeff() / speed;
    const double injectionTime = rounded(transitsInjected * transit);
    const double endTime = rounded(transitsTracked * transit);

    particles(text, !injectsOnInletPatch(outline));
    inletInjection(text, outline, injectionTime, speed);
    physics(text, "(0 0 0)", "the case's down, e.g. (0 -9.81 0)");
    time(text, endTime);
    surfaces(text, outline);
    const double margin = domainMargin * extent.maxCoeff();
    const Vec3 widen = Vec3::Constant(margin);
    domain(text, {outline.bounds.min - widen, outline.bounds.max + widen},
           "The mesh's box" +
               std::string(outline.shape == FoamMeshShape::wedge
                               ? " (the wedge swept about its axis)"
                               : "") +
               ", " + number(domainMargin * 100) +
               " % of its largest extent wider on every side so that the inlet on its face "
               "lies inside; the mesh's patches end a particle's path first.");
    output(text, endTime);
    text.raw(footer);
    return text.text();
}

/// The analytic sech² jet of foamCases/analyticSpray: a round nozzle of 2 mm at the origin
/// blowing at 25 m/s along x onto a plate 60 mm away.
std::string analyticTemplate() {
    CommentedDictionary text;
    text.raw(header("no OpenFOAM mesh\n  here, so the carrier is the analytic sech² jet "
                    "(Eq. 5.10/5.11) of foamCases/analyticSpray."));
    fluid(text, airKinematicViscosity, "air at 20 °C");
    const double standoff = 0.06, nozzleVelocity = 25, nozzleRadius = 2e-3;
    text.open("carrier");
    text.entry("type", "analyticJet");
    text.open("analyticJetCoeffs");
    text.defaultEntry("profile");
    text.entry("nozzleVelocity", number(nozzleVelocity));
    text.entry("coreLength", number(4 * nozzleRadius), "four nozzle radii");
    text.entry("effectiveViscosity", "1.4e-3",
               "eddy viscosity 0.028 R U0 of a turbulent round jet (Pope)");
    text.close();
    text.close();
    particles(text, true);
    const Box box{{-0.005, -0.03, -0.03}, {standoff + 0.005, 0.03, 0.03}};
    const double transit = (box.max - box.min).maxCoeff() / nozzleVelocity;
    const double endTime = rounded(transitsTracked * transit);
    nozzleInjection(text, Vec3::Zero(), Vec3::UnitX(), nozzleRadius, Vec3::UnitY(),
                    rounded(transitsInjected * transit), standoff, "The jet's round nozzle.");
    physics(text, "(0 -9.81 0)", "y up");
    time(text, endTime);
    text.open("surfaces");
    text.note("A plate across the jet, " + number(standoff) + " m from the nozzle.");
    text.open("target");
    text.entry("type", "plane");
    text.entry("point", vectorText({standoff, 0, 0}));
    text.entry("normal", "(-1 0 0)");
    text.defaultEntry("interaction");
    text.close();
    text.close();
    domain(text, box, "Particles leaving this box escape.");
    output(text, endTime);
    text.raw(footer);
    return text.text();
}

} // namespace

std::string caseTemplate(const fs::path& caseDirectory) {
    const fs::path mesh = caseDirectory / "constant" / "polyMesh";
    if (fs::exists(mesh)) return foamTemplate(caseDirectory);
    if (fs::exists(caseDirectory / "system" / "controlDict"))
        throw InputError(mesh.string(), 0, "",
                         "missing: an OpenFOAM case (system/controlDict) without its mesh; run "
                         "its Allrun (blockMesh, the solver) first, then --init");
    return analyticTemplate();
}

fs::path writeCaseTemplate(const fs::path& caseDirectory) {
    const fs::path file = caseDirectory / "constant" / "slidesProperties";
    if (!fs::is_directory(caseDirectory))
        throw InputError(caseDirectory.string(), 0, "",
                         "not a directory: --init writes constant/slidesProperties into a case "
                         "directory");
    if (fs::exists(file))
        throw InputError(file.string(), 0, "",
                         "exists already; --init never overwrites a case dictionary: edit it, "
                         "or move it aside (e.g. to slidesProperties.orig) and run --init again");
    const std::string text = caseTemplate(caseDirectory);
    fs::create_directories(file.parent_path());
    writeTextAtomically(file, text);
    return file;
}

} // namespace slides
