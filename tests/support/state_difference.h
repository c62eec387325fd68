// How far apart two states are: the largest difference of their unknowns over the
// largest unknown of the reference, the measure the tests' "same state" tolerances are
// stated in.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace twb::testing {

template <class State, class Reference>
double relative_difference(const State& state, const Reference& reference) {
  double difference = 0.0, size = 0.0;
  for (std::size_t k = 0; k < std::size(reference); ++k) {
    difference = std::max(difference, std::abs(state[k] - reference[k]));
    size = std::max(size, std::abs(reference[k]));
  }
  return difference / size;
}

}  // namespace twb::testing
