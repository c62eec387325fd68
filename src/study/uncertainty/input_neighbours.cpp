#include "study/uncertainty/input_neighbours.h"

#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "twb/input_error.h"
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

// The bearings at the stencil's points; InputError where one leaves the input's range.
std::vector<std::unique_ptr<BearingModel>> built_at(const BearingModel& base, const SceneInput& input, double step,
                                                    const Stencil& stencil) {
  std::vector<std::unique_ptr<BearingModel>> at;
  for (const double offset : stencil.offsets) {
    const double value = input.value + offset * step;
    const std::pair<std::string, double> set[] = {{input.path, value}};
    // The load's neighbours keep the base's scales (its pressure scale is the scene
    // load's): a load is set on a built model, as a continuation sets it.
    at.push_back(std::make_unique<BearingModel>(input.path == kLoadInput ? base.scene() : with_inputs(base.scene(), set)));
    at.back()->set_speed(input.path == kSpeedInput ? value : base.speed());
    // (The Jacobian's pattern may differ: it is the cold start's, and only the residual
    // is differenced.)
    if (at.back()->size() != base.size())
      throw std::invalid_argument(fmt::format("{} changes the bearing's unknowns within ±{:.3g} {}: a discrete input",
                                              input.path, 4.0 * step, input.unit));
  }
  return at;
}

}  // namespace

std::vector<double> stencil_derivative(const Stencil& stencil, double step,
                                       const std::function<std::vector<double>(std::size_t)>& value_at) {
  std::vector<double> derivative;
  for (std::size_t k = 0; k < stencil.offsets.size(); ++k) {
    const std::vector<double> v = value_at(k);
    if (derivative.empty()) derivative.assign(v.size(), 0.0);
    for (std::size_t j = 0; j < v.size(); ++j) derivative[j] += stencil.weights[k] * v[j] / (12.0 * step);
  }
  return derivative;
}

std::vector<double> moved_state(std::span<const double> u, std::span<const double> direction, double s) {
  std::vector<double> moved(u.begin(), u.end());
  for (std::size_t j = 0; j < moved.size(); ++j) moved[j] -= s * direction[j];
  return moved;
}

double InputNeighbours::load_at(std::size_t k, double load) const {
  return input.path == kLoadInput ? load + stencil.offsets[k] * step : load;
}

InputNeighbours input_neighbours(const BearingModel& base, SceneInput input, int order) {
  // The operating point stands where the base model stands (a Bearing solves at loads and
  // speeds of its own), not where the scene file put it.
  if (input.path == kLoadInput) input.value = base.load();
  if (input.path == kSpeedInput) input.value = base.speed();
  InputNeighbours n;
  n.input = input;
  n.step = kInputStep * (input.value != 0.0 ? std::abs(input.value) : step_floor(input.unit));
  std::optional<InputError> first;
  const std::array<const Stencil*, 3> stencils =
      order == 2 ? std::array{&kCentred2, &kForward2, &kBackward2} : std::array{&kCentred, &kForward, &kBackward};
  for (const Stencil* stencil : stencils) {
    try {
      n.at = built_at(base, input, n.step, *stencil);
      n.stencil = *stencil;
      return n;
    } catch (const InputError& e) {
      if (!first) first = e;  // the centred stencil's: a bound's, which the user reads
    }
  }
  throw *first;
}

std::vector<double> residual_derivative(InputNeighbours& n, std::span<const double> u, double load) {
  std::vector<double> f(u.size());
  return n.derivative([&](std::size_t k) {
    n.at[k]->set_load(n.load_at(k, load));
    n.at[k]->evaluate(u, f, {});
    return f;
  });
}

}  // namespace twb
