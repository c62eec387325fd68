// The washer unloaded at rest (docs/physics.md section 19). With the load and the speed
// both zero no force acts on the washer and the gear: neither film lifts, and their
// contact can only push them apart, which a massless body follows without limit (the
// gear up film 2's asperity tail, as far as its stop). Where bodies with mass would stay
// where they came to rest, the rigid rows say so: the rigid unknowns are held at the
// values they had when the washer came to rest, a differential one (the sliding film's,
// whose rate its squeeze reads) in real time by a rate of zero, so that the march's DAE
// keeps its index.
#include "model/bearing_model.h"
#include "twb/error_family.h"

namespace twb {

void BearingModel::hold_at_rest(std::span<const double> u) {
  if (u.empty()) {
    rest_.clear();
    return;
  }
  if (u.size() != std::size_t(size())) throw InternalError("hold_at_rest: size mismatch");
  rest_.assign(u.begin() + rigid_offset_, u.begin() + rigid_offset_ + 4);
  const std::vector<char> differential = rate_unknowns();
  for (Index k = 0; k < 4; ++k) rest_by_rate_[std::size_t(k)] = differential[std::size_t(rigid_offset_ + k)];
}

// Each rigid row becomes its unknown's distance from the held value, or (in real time,
// a differential unknown) its rate in σ (or γ_ref) per second: the rows' Jacobian in the
// pattern is then its diagonal alone, +1 or c_j (oriented as every row, positive).
void BearingModel::add_rest_rows(std::span<const double> u, Assembler& a, const StateRates* rates) const {
  if (a.mode() != Assembler::Mode::values) return;
  for (Index k = 0; k < 4; ++k) {
    const Index row = rigid_offset_ + k;
    const bool by_rate = rates && rest_by_rate_[std::size_t(k)] != 0;
    a.set_residual(row, by_rate ? rates->rate[std::size_t(row)] : u[std::size_t(row)] - rest_[std::size_t(k)]);
    if (!a.wants_jacobian()) continue;
    a.scale_row(row, 0.0);
    a.add_derivative(row, row, by_rate ? rates->cj : 1.0);
  }
}

}  // namespace twb
