#include "study/input_neighbours.h"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "twb/scene/scene_inputs.h"

namespace twb {

namespace {


// δ's unit of size where the input is zero (δ is relative otherwise): a tilt of a
// milliradian, a supply of a bar, a micrometre; one of the SI unit for the rest.
double step_floor(const std::string& unit) {
  if (unit == "rad") return 1e-3;
  if (unit == "Pa") return 1e5;
  if (unit == "m") return 1e-6;
  return 1.0;
}

}  // namespace

double InputNeighbours::load_at(std::size_t k, double load) const {
  return input.path == kLoadInput ? load + kOffsets[k] * step : load;
}

InputNeighbours input_neighbours(const BearingModel& base, SceneInput input) {
  // The operating point stands where the base model stands (a Bearing solves at loads and
  // speeds of its own), not where the scene file put it.
  if (input.path == kLoadInput) input.value = base.load();
  if (input.path == kSpeedInput) input.value = base.speed();
  InputNeighbours n;
  n.input = input;
  n.step = kInputStep * (input.value != 0.0 ? std::abs(input.value) : step_floor(input.unit));
  for (std::size_t k = 0; k < 4; ++k) {
    const double value = input.value + InputNeighbours::kOffsets[k] * n.step;
    const std::pair<std::string, double> set[] = {{input.path, value}};
    // The load's neighbours keep the base's scales (its pressure scale is the scene
    // load's): a load is set on a built model, as a continuation sets it.
    n.at[k] = std::make_unique<BearingModel>(input.path == kLoadInput ? base.scene() : with_inputs(base.scene(), set));
    n.at[k]->set_speed(input.path == kSpeedInput ? value : base.speed());
    // (The Jacobian's pattern may differ: it is the cold start's, and only the residual
    // is differenced.)
    if (n.at[k]->size() != base.size())
      throw std::invalid_argument(fmt::format("{} changes the bearing's unknowns within ±{:.3g} {}: a discrete input",
                                              input.path, 2.0 * n.step, input.unit));
  }
  return n;
}

std::vector<double> residual_derivative(InputNeighbours& n, std::span<const double> u, double load) {
  const auto size = u.size();
  std::vector<double> f(size), derivative(size, 0.0);
  for (std::size_t k = 0; k < 4; ++k) {
    n.at[k]->set_load(n.load_at(k, load));
    n.at[k]->evaluate(u, f, {});
    const double w = InputNeighbours::kWeights[k] / (12.0 * n.step);
    for (std::size_t i = 0; i < size; ++i) derivative[i] += w * f[i];
  }
  return derivative;
}

std::vector<double> neighbour_derivative(double step,
                                         const std::function<std::vector<double>(std::size_t)>& value_at) {
  std::vector<double> derivative;
  for (std::size_t k = 0; k < 4; ++k) {
    const std::vector<double> v = value_at(k);
    if (derivative.empty()) derivative.assign(v.size(), 0.0);
    for (std::size_t j = 0; j < v.size(); ++j) derivative[j] += InputNeighbours::kWeights[k] * v[j] / (12.0 * step);
  }
  return derivative;
}

}  // namespace twb
