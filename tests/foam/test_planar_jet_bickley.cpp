// ctest-labels: carrier verification
// foam-cases: planarJet
// OpenFOAM's laminar planar jet (foamCases/planarJet: simpleFoam, slot Reynolds number 100)
// against Bickley's similarity solution, Eq. 5.10/5.11 of the reference (Bickley 1937;
// Schlichting, Boundary-Layer Theory, "plane jet"): centreline speed ∝ x^(−1/3), half-width
// ∝ x^(2/3), u/u_c = sech²η, and the amplitude C1 = (3K²/(32ν))^(1/3) set by the momentum flux
// K = ∫u² dy, which the jet conserves. The analytic carrier's BickleyProfile, built from the K
// measured in the OpenFOAM solution, is compared point by point, so this checks both carriers.
// Profiles come from OpenFOAM's own sampling (system/sampleProfiles: x = 60…160 mm, i.e. 30–80
// slot widths, far enough for similarity); the virtual origin x0 is fitted.
#include "slides/carrier/analytic_jet.h"
#include "slides/config/dictionary.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace slides {
namespace {

namespace fs = std::filesystem;

const fs::path caseDirectory = fs::path(SLIDES_FOAM_RUNS_DIR) / "planarJet";

/// One `raw` line set written by OpenFOAM's `sets` function object: distance, Ux, Uy, Uz.
struct Profile {
    double x = 0; ///< station [m]
    std::vector<double> y, u, v;
};

fs::path latestSampleDirectory() {
    const fs::path root = caseDirectory / "postProcessing" / "sampleProfiles";
    if (!fs::is_directory(root))
        throw std::runtime_error(root.string() + " missing: run foamCases/planarJet/Allrun");
    fs::path latest;
    double latestTime = -1;
    for (const auto& entry : fs::directory_iterator(root)) {
        const double time = std::stod(entry.path().filename().string());
        if (time > latestTime) {
            latestTime = time;
            latest = entry.path();
        }
    }
    return latest;
}

Profile readProfile(const fs::path& file, double x) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error("cannot read " + file.string());
    Profile profile;
    profile.x = x;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream columns(line);
        double y, ux, uy, uz;
        if (columns >> y >> ux >> uy >> uz) {
            profile.y.push_back(y);
            profile.u.push_back(ux);
            profile.v.push_back(uy);
        }
    }
    if (profile.y.size() < 10) throw std::runtime_error(file.string() + ": fewer than 10 samples");
    return profile;
}

/// The stations x060 … x160 (name = x in mm).
std::vector<Profile> readStations() {
    const fs::path directory = latestSampleDirectory();
    std::vector<Profile> stations;
    for (int millimetres : {60, 80, 100, 120, 140, 160}) {
        char name[32];
        std::snprintf(name, sizeof name, "x%03d_U.xy", millimetres);
        stations.push_back(readProfile(directory / name, millimetres * 1e-3));
    }
    return stations;
}

double centrelineSpeed(const Profile& p) { return p.u.front(); } // y = 0 is the symmetry plane

/// y where u falls to half the centreline speed (linear between samples).
double halfWidth(const Profile& p) {
    const double half = 0.5 * centrelineSpeed(p);
    for (std::size_t i = 1; i < p.y.size(); ++i)
        if (p.u[i] < half)
            return p.y[i - 1] + (half - p.u[i - 1]) * (p.y[i] - p.y[i - 1]) / (p.u[i] - p.u[i - 1]);
    throw std::runtime_error("profile never falls to half its centreline speed");
}

/// K = ∫u² dy over the whole jet (both halves; trapezoidal rule) [m³/s²].
double momentumFlux(const Profile& p) {
    double integral = 0;
    for (std::size_t i = 1; i < p.y.size(); ++i)
        integral += 0.5 * (p.u[i] * p.u[i] + p.u[i - 1] * p.u[i - 1]) * (p.y[i] - p.y[i - 1]);
    return 2 * integral;
}

struct PowerLaw {
    double exponent = 0, origin = 0; ///< q = A (x − origin)^exponent
};

/// Least squares of log q against log(x − x0) for every x0 on a 10 µm grid over ±50 mm; the
/// x0 with the smallest residual (the similarity solution's virtual origin) wins.
PowerLaw fitPowerLaw(const std::vector<double>& x, const std::vector<double>& q) {
    PowerLaw best;
    double bestResidual = INFINITY;
    for (double origin = -0.05; origin <= 0.05; origin += 1e-5) {
        const auto n = static_cast<double>(x.size());
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (std::size_t i = 0; i < x.size(); ++i) {
            const double lx = std::log(x[i] - origin), ly = std::log(q[i]);
            sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
        }
        const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
        const double intercept = (sy - slope * sx) / n;
        double residual = 0;
        for (std::size_t i = 0; i < x.size(); ++i) {
            const double r = std::log(q[i]) - intercept - slope * std::log(x[i] - origin);
            residual += r * r;
        }
        if (residual < bestResidual) {
            bestResidual = residual;
            best = {slope, origin};
        }
    }
    return best;
}

void measured(const std::string& what, double value) {
    ::testing::Test::RecordProperty(what, std::to_string(value));
    std::cout << "[ measured ] " << what << " = " << value << '\n';
}

class PlanarJet : public testing::Test {
protected:
    static void SetUpTestSuite() {
        stations_ = readStations();
        for (const Profile& p : stations_) {
            x_.push_back(p.x);
            centreline_.push_back(centrelineSpeed(p));
            width_.push_back(halfWidth(p));
        }
    }
    static double viscosity() {
        return Dictionary::parseFile(caseDirectory / "constant" / "transportProperties")
            .scalar("nu");
    }
    static inline std::vector<Profile> stations_;
    static inline std::vector<double> x_, centreline_, width_;
};

TEST_F(PlanarJet, CentrelineSpeedDecaysAsXToMinusOneThird) {
    // u_c = C1 (x − x0)^(−1/3). The fitted exponent is −0.3346 on this mesh; ±0.01 (3 %) allows
    // for the mesh and the last traces of the slot's top-hat profile, and still fails for any
    // other jet (round laminar: −1; turbulent planar: −1/2).
    const PowerLaw fit = fitPowerLaw(x_, centreline_);
    measured("centreline exponent", fit.exponent);
    measured("centreline virtual origin [m]", fit.origin);
    EXPECT_NEAR(fit.exponent, -1.0 / 3.0, 0.01);
}

TEST_F(PlanarJet, HalfWidthGrowsAsXToTwoThirds) {
    // b = 0.8814 (x − x0)^(2/3) / C3 (sech² 0.8814 = 1/2). Fitted: 0.6654; tolerance as above
    // (turbulent planar and round jets spread as x^1).
    const PowerLaw fit = fitPowerLaw(x_, width_);
    measured("half-width exponent", fit.exponent);
    measured("half-width virtual origin [m]", fit.origin);
    EXPECT_NEAR(fit.exponent, 2.0 / 3.0, 0.01);
    // Both fits see the same similarity solution, so their virtual origins agree (found: within
    // 0.7 mm, against stations 60–160 mm downstream); 3 mm = 1.5 slot widths.
    EXPECT_NEAR(fit.origin, fitPowerLaw(x_, centreline_).origin, 3e-3);
}

TEST_F(PlanarJet, MomentumFluxIsConserved) {
    // A free jet in still air at uniform pressure keeps K = ∫u² dy: the stations agree within
    // 0.1 % here; 1 % leaves room for the sampling (0.1 mm spacing) and the open boundaries.
    const double first = momentumFlux(stations_.front());
    for (const Profile& p : stations_) {
        EXPECT_NEAR(momentumFlux(p) / first, 1.0, 0.01) << "x = " << p.x;
        measured("K(x = " + std::to_string(p.x) + ") [m^3/s^2]", momentumFlux(p));
    }
}

TEST_F(PlanarJet, ProfilesMatchTheAnalyticCarrier) {
    // The analytic carrier's Bickley profile with ν of the case and the K measured here, at
    // s = x − x0 (x0 of the centreline fit): every sampled u within 2 % of the local centreline
    // speed (found: 0.64 %; a top-hat or Gaussian profile of the
    // same width and flux misses sech² by more than 5 %).
    double flux = 0;
    for (const Profile& p : stations_)
        flux += momentumFlux(p) / static_cast<double>(stations_.size());
    const double nu = viscosity();
    const BickleyProfile bickley{.C1 = std::cbrt(3 * flux * flux / (32 * nu)),
                                 .C2 = std::cbrt(flux * nu / 6),
                                 .C3 = std::cbrt(flux / (48 * nu * nu))};
    const double origin = fitPowerLaw(x_, centreline_).origin;
    double worst = 0;
    for (const Profile& p : stations_) {
        const double s = p.x - origin;
        const double uc = centrelineSpeed(p);
        for (std::size_t i = 0; i < p.y.size(); ++i) {
            const double deviation = std::abs(p.u[i] - bickley.at(s, p.y[i]).u) / uc;
            worst = std::max(worst, deviation);
            ASSERT_LT(deviation, 0.02) << "x = " << p.x << ", y = " << p.y[i];
        }
    }
    measured("max |u_foam - u_Bickley| / u_c", worst);
}

} // namespace
} // namespace slides
