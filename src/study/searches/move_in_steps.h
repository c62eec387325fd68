// A move a solver makes from where it stands to where it is asked (other inputs, another
// load) in steps: each step's end is tried, the step halved where the solver cannot take
// it (down to `least` of the move) and doubled after it took one. The failure load's
// moves between inputs (failure_at_inputs.cpp) and the states' (operating_states.cpp)
// walk so; the steady solver's ramps and the operating states' climb to a limit keep
// their own positions (a load or speed added to, a load scaled) with the same step.
#pragma once

#include <algorithm>
#include <functional>

namespace twb {

// A step's length: halved where the solver cannot take it, never below `least`, and
// lengthened by `growth` after one it took.
class StepLength {
 public:
  StepLength(double first, double least, double growth) : length_(first), least_(least), growth_(growth) {}
  double value() const { return length_; }
  // False, the length unchanged, where half of it would be below `least`: the move stops.
  bool halve() {
    if (0.5 * length_ < least_) return false;
    length_ *= 0.5;
    return true;
  }
  void lengthen() { length_ *= growth_; }
  // No longer than what is left of the move.
  void at_most(double left) { length_ = std::min(length_, left); }

 private:
  double length_, least_, growth_;
};

enum class StepTaken { yes, no, never };  // never: no shorter step can be taken either

// `step(done, reached)`: the step from fraction `done` of the move to `reached` (exactly
// 1 for the last one). Whether the whole move was made.
inline bool move_in_steps(double least, const std::function<StepTaken(double done, double reached)>& step) {
  double done = 0.0;
  StepLength length(1.0, least, 2.0);
  while (done < 1.0) {
    length.at_most(1.0 - done);
    const double reached = done + length.value() < 1.0 ? done + length.value() : 1.0;
    const StepTaken taken = step(done, reached);
    if (taken == StepTaken::never) return false;
    if (taken == StepTaken::no) {
      if (!length.halve()) return false;
      continue;
    }
    done = reached;
    length.lengthen();
  }
  return true;
}

}  // namespace twb
