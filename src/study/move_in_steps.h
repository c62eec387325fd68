// A move a solver makes from where it stands to where it is asked (other inputs, another
// load) in steps: each step's end is tried, the step halved where the solver cannot take
// it (down to `least` of the move) and doubled after it took one. The failure load's
// moves between inputs (failure_at_inputs.cpp) and the states' (operating_states.cpp)
// walk so.
#pragma once

#include <algorithm>
#include <functional>

namespace twb {

enum class StepTaken { yes, no, never };  // never: no shorter step can be taken either

// `step(done, reached)`: the step from fraction `done` of the move to `reached` (exactly
// 1 for the last one). Whether the whole move was made.
inline bool move_in_steps(double least, const std::function<StepTaken(double done, double reached)>& step) {
  double done = 0.0, length = 1.0;
  while (done < 1.0) {
    length = std::min(length, 1.0 - done);
    const double reached = done + length < 1.0 ? done + length : 1.0;
    const StepTaken taken = step(done, reached);
    if (taken == StepTaken::never) return false;
    if (taken == StepTaken::no) {
      if (0.5 * length < least) return false;
      length *= 0.5;
      continue;
    }
    done = reached;
    length *= 2.0;
  }
  return true;
}

}  // namespace twb
