#include "slides/physics/michaelides_feng.h"

#include <cmath>
#include <numbers>

namespace slides {

MichaelidesFengRates michaelidesFengRates(double particleDensity, double particleSpecificHeat,
                                          double particleRadius, double fluidDensity,
                                          double fluidSpecificHeat,
                                          double fluidThermalConductivity) {
    const double particleCapacity = particleDensity * particleSpecificHeat; // ρp c_p
    const double fluidCapacity = fluidDensity * fluidSpecificHeat;          // ρf c_f
    const double diffusivity = fluidThermalConductivity / fluidCapacity;    // κ_f
    const double conduction = 3 * fluidThermalConductivity / particleCapacity;
    return {conduction / (particleRadius * particleRadius),
            conduction / (particleRadius * std::sqrt(std::numbers::pi * diffusivity)),
            fluidCapacity / particleCapacity};
}

double advanceMichaelidesFeng(const MichaelidesFengRates& rates, const WindowTailLayout& layout,
                              double* state, double temperature, double gasTemperature, double h) {
    if (h == 0) return temperature; // injected at the step's end
    double& age = state[0];
    double& lastGasTemperature = state[1];
    Eigen::Map<Vec3> startDifference(state + 2), integral(state + 5);
    if (age == 0) { // released now: the jump θf − θp starts the conduction layer
        lastGasTemperature = gasTemperature;
        startDifference = Vec3(gasTemperature - temperature, 0, 0);
    }
    // m_f c_f dθf/dt along the path, integrated over the step (a total derivative).
    temperature += rates.fluidCapacityRatio * (gasTemperature - lastGasTemperature);
    SlipStep step;
    step.h = h;
    step.dragRate = rates.conductionRate;
    step.historyRate = rates.historyRate;
    step.gasStart = step.gasEnd = Vec3(gasTemperature, 0, 0);
    HistoryStart start{startDifference, age, integral};
    WindowTailHistory memory(layout, state + 8);
    const double next =
        advanceWithHistory(step, Vec3(temperature, 0, 0), start, memory).velocity.x();
    integral = start.integral;
    age += h;
    lastGasTemperature = gasTemperature;
    return next;
}

} // namespace slides
