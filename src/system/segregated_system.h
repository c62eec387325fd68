// What a segregated scheme needs of a system beyond its monolithic form (the paper's
// Fig. 5 algorithm, paper_scheme.h): which unknowns are the rigid body's, which the
// film pressures' and which the temperatures', and the pressure rows as plain flow
// balances, since the scheme keeps p ≥ 0 itself, by projection, instead of through a
// complementarity row.
#pragma once

#include <vector>

#include "system/steady_system.h"

namespace twb {

class SegregatedSystem : public SteadySystem {
 public:
  struct Blocks {
    std::vector<Index> rigid;        // solved by the outer Newton–Raphson (eqs [34]-[37])
    std::vector<Index> pressure;     // by projected SOR on the Reynolds flow balance
    std::vector<Index> temperature;  // by Gauss–Seidel on the heat balance
  };
  virtual Blocks segregated_blocks() const = 0;
  // On: each pressure row is the node's scaled flow balance ŵ (linear in the pressures
  // for a given film and viscosity), whatever the sign of p; off: the complementarity row.
  virtual void set_flow_balance_rows(bool on) = 0;
};

// The flow-balance rows while the scope lives.
class FlowBalanceRows {
 public:
  explicit FlowBalanceRows(SegregatedSystem& system) : system_(system) { system_.set_flow_balance_rows(true); }
  ~FlowBalanceRows() { system_.set_flow_balance_rows(false); }
  FlowBalanceRows(const FlowBalanceRows&) = delete;
  FlowBalanceRows& operator=(const FlowBalanceRows&) = delete;

 private:
  SegregatedSystem& system_;
};

}  // namespace twb
