// ctest-labels: turbulence heat run
// The default spray (foamCases/analyticSpray) with 5 µm particles in a turbulent, cold jet:
// the dictionary blocks of dispersion, heat transfer and jet turbulence read and run together.
//  - Dispersion spreads the deposit: the radial spread of arrivals grows over the laminar run.
//  - Heating: every arrival temperature lies between the gas temperature and the bound of the
//    slowest possible cooling, Nu = 2 (Nu ≥ 2 for every correlation, Eq. 3.27):
//    θf < θ ≤ θf + (θ0 − θf) e^(−(t − t_in)/τ_θ(Nu = 2)).
//  - Output: frames carry a temperature array, the summary arrival temperature statistics.
//  - Dispersion without k, ε for the analytic jet is an input error naming the key.
#include "../support/test_scenes.h"
#include "slides/config/dictionary.h"
#include "slides/config/scene_reader.h"
#include "slides/core/error.h"
#include "slides/io/run_output.h"
#include "slides/run/run_report.h"
#include "slides/run/stepper.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace slides {
namespace {

const std::filesystem::path defaultCase =
    std::filesystem::path(SLIDES_SOURCE_DIR) / "foamCases" / "analyticSpray";

/// The default dictionary with extra physics entries and, if given, jet turbulence.
Scene sprayScene(const std::string& physics, const std::string& turbulence) {
    std::ifstream in(defaultCase / "constant" / "slidesProperties");
    std::stringstream buffer;
    buffer << in.rdbuf();
    std::string text = buffer.str();
    const auto insert = [&](const std::string& after, const std::string& entry) {
        const auto at = text.find(after);
        ASSERT_NE(at, std::string::npos) << after;
        text.insert(at + after.size(), entry);
    };
    insert("    buoyancy    on;\n", physics);
    insert("        effectiveViscosity 1.4e-3;\n    }\n", turbulence);
    insert("    density     5680;\n", "    specificHeat 460;\n    injectionTemperature 600;\n");
    Scene scene =
        sceneFromDictionary(Dictionary::parseString(text, "slidesProperties"), defaultCase);
    scene.particles.count = 2000;
    scene.particles.radius.value = 5e-6; // τ_St ≈ 1 ms: follows the eddies
    scene.time.endTime = 8e-3;           // all injected by 2.5 ms; most arrive by then
    return scene;
}

const std::string jetTurbulence =
    "    turbulence { scaling jetLocal; intensity 0.25; lengthScaleToHalfWidth 0.2; }\n";
const std::string dispersionAndHeat = "    dispersion { model eddyInteraction; }\n"
                                      "    heatTransfer { model ranzMarshall; }\n";

/// Arrivals of a whole run.
std::vector<Arrival> run(const Scene& scene) {
    const auto carrier = test::carrierOf(scene);
    Stepper stepper(scene, *carrier);
    while (!stepper.finished()) stepper.step();
    return stepper.arrivals();
}

double radialSpread(const std::vector<Arrival>& arrivals) {
    double sum = 0;
    for (const Arrival& arrival : arrivals) {
        const Vec3& x = arrival.position;
        sum += x.y() * x.y() + x.z() * x.z();
    }
    return std::sqrt(sum / static_cast<double>(arrivals.size()));
}

TEST(TurbulentSpray, DispersionWidensTheDepositAndHeatingStaysWithinItsBounds) {
    const Scene laminar = sprayScene("", "");
    const Scene turbulent = sprayScene(dispersionAndHeat, jetTurbulence);
    const auto calm = run(laminar);
    const auto dispersed = run(turbulent);
    ASSERT_GT(calm.size(), 1000u);
    ASSERT_GT(dispersed.size(), 1000u);
    // The rms radius of 1000+ arrivals has a relative standard error of a few per cent; the
    // turbulence (u' = 0.25 U_c) must widen it by far more than that.
    EXPECT_GT(radialSpread(dispersed), 1.2 * radialSpread(calm))
        << radialSpread(dispersed) << " m against " << radialSpread(calm) << " m";

    const double gas = turbulent.fluid.temperature;
    const double slowest =
        thermalResponseTime(turbulent.particles.density, turbulent.particles.specificHeat, 5e-6,
                            2.0, turbulent.fluid.thermalConductivity);
    for (const Arrival& arrival : dispersed) {
        const double flight =
            arrival.time - static_cast<double>(arrival.id) / turbulent.injection.rate;
        EXPECT_GT(arrival.temperature, gas) << "particle " << arrival.id;
        EXPECT_LE(arrival.temperature,
                  gas + (600 - gas) * std::exp(-flight / slowest) * (1 + 1e-12))
            << "particle " << arrival.id;
    }
}

TEST(TurbulentSpray, FramesAndSummaryCarryTheTemperature) {
    Scene scene = sprayScene(dispersionAndHeat, jetTurbulence);
    scene.output.carrierResolution = {4, 4, 4};
    const auto carrier = test::carrierOf(scene);
    Stepper stepper(scene, *carrier);
    const auto directory = std::filesystem::temp_directory_path() /
                           ("slides-turbulent-spray-" + std::to_string(::getpid()));
    {
        RunOutput output(directory, runOutputSettings(scene));
        while (!stepper.finished()) stepper.step();
        output.writeFrame(stepper.snapshot());
        const auto summary = runSummary(stepper.snapshot(), summaryInputs(scene), RunMetrics{});
        const auto& temperature = summary["arrivals"]["target"]["temperature"];
        ASSERT_TRUE(temperature.is_object()) << summary["arrivals"].dump();
        EXPECT_GT(temperature["min"].get<double>(), scene.fluid.temperature);
        EXPECT_LT(temperature["max"].get<double>(), 600.0);
    }
    std::ifstream frame(directory / "particles_000000.vtp");
    std::stringstream xml;
    xml << frame.rdbuf();
    EXPECT_NE(xml.str().find("Name=\"temperature\""), std::string::npos);
    std::filesystem::remove_all(directory);
}

TEST(TurbulentSpray, DispersionWithoutJetTurbulenceIsAnInputError) {
    try {
        sprayScene(dispersionAndHeat, "");
        FAIL() << "expected an InputError";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("carrier.turbulence"), std::string::npos)
            << error.what();
    }
}

} // namespace
} // namespace slides
