// The statistical contact pressure of a summit population scaled by k = σ/σ0 (docs/physics.md
// sections 4 and 20: a face running in changes its Rq, and its summits follow the
// roughness as §4 scales them, σs by k, R by 1/k, η kept), p(h, k) for k in [k_low, 1].
//
// Greenwood–Williamson summation of Hertz summits is scale-invariant under this scaling:
// p(h; k) = k·p(h/k; 1). Jackson–Green summits are not (their critical interference goes
// with R·(S_y/E)², so a smoother population yields at other separations), so p is
// tabulated: a table in h (statistical_contact.h) at each of a few k_j, uniform in ln k,
// and between them
//
//   ln p(h, k) = ln k + G(h/k, ln k),   G(x, ln k_j) = ln p_j(k_j·x) − ln k_j
//
// interpolated in ln k by the cubic through the four nearest k_j at the same x: G would
// not depend on k at all for Hertz summits, and changes slowly with k as Jackson–Green's
// plastic share moves. Its error is measured at construction against a table built at
// the midpoint of every interval of k (error_bound()), as the one-dimensional table's
// error is.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "physics/contact_table_cache.h"
#include "physics/statistical_contact.h"

namespace twb {

class ScaledContact {
 public:
  // `key`: the population at k = 1 (the new faces'); k_low in (0, 1]: the least scale
  // asked (the faces run in). Each interval of ln k at most `spacing` wide.
  ScaledContact(const ContactTableKey& key, double k_low, double spacing = 0.1);

  struct Pressure {
    double value = 0.0, dh = 0.0, dk = 0.0;  // p (Pa), ∂p/∂h (Pa/m), ∂p/∂k (Pa)
  };
  // p(h, k) and its slopes; k is held within [k_low, 1] (beyond them, the nearest end's,
  // with no slope in k; at the ends themselves, the interpolant's one-sided slope).
  Pressure pressure(double h, double k) const;
  // The summits in contact at (h, k): their count per unit area and the real area's share
  // (the flash temperature's junctions, docs/physics.md section 8).
  StatisticalContact::SummitContacts contacts(double h, double k) const;

  // The largest relative error of p found at the midpoints in ln k between the tables,
  // over the separations where p is above 1e-30 of its value at contact (the model's
  // cutoff), against a table built there.
  double error_bound() const { return error_bound_; }
  double k_low() const { return k_low_; }
  // The population at k (σs·k, R/k, η kept): its own table, for tests and the error check.
  static ContactTableKey scaled(const ContactTableKey& key, double k);

 private:
  // G and its slopes in x and ln k at (x, ln k), from the four tables nearest ln k.
  struct Reduced {
    double g = 0.0, dx = 0.0, dlnk = 0.0;
    bool zero = false;  // p underflows at a table: no contact
  };
  Reduced reduced(double x, double lnk) const;
  // The Lagrange cubic's nodes nearest ln k (first, count) and its weights and their slopes.
  struct Stencil {
    int first = 0, count = 0;
    std::array<double, 4> w{}, dw{};
  };
  Stencil stencil(double lnk) const;

  double k_low_, step_;
  std::vector<double> lnk_;  // the nodes, from ln k_low to 0
  std::vector<std::shared_ptr<const StatisticalContact>> tables_;
  double error_bound_ = 0.0;
};

// The scaled contact for (key, k_low), built on first use; the most recent few are kept.
std::shared_ptr<const ScaledContact> shared_scaled_contact(const ContactTableKey& key, double k_low);

}  // namespace twb
