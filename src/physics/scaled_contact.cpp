#include "physics/scaled_contact.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <tuple>
#include <utility>

#include <fmt/format.h>

namespace twb {

ContactTableKey ScaledContact::scaled(const ContactTableKey& key, double k) {
  ContactTableKey s = key;
  s.summit_sigma *= k;
  s.summit_radius /= k;
  return s;
}

ScaledContact::ScaledContact(const ContactTableKey& key, double k_low, double spacing) : k_low_(k_low) {
  if (!(k_low > 0.0 && k_low <= 1.0))
    throw std::invalid_argument(fmt::format("ScaledContact: the least scale {} is not within (0, 1]", k_low));
  if (!(spacing > 0.0)) throw std::invalid_argument("ScaledContact: the spacing in ln k must be positive");
  const double span = -std::log(k_low);
  const int intervals = span > 0.0 ? std::max(3, int(std::ceil(span / spacing))) : 0;
  step_ = intervals > 0 ? span / intervals : 1.0;
  for (int j = 0; j <= intervals; ++j) {
    lnk_.push_back(j == intervals ? 0.0 : -span + j * step_);
    tables_.push_back(shared_contact_table(scaled(key, std::exp(lnk_.back()))));
  }
  // The interpolation's error, where the cubic in ln k errs most: at each interval's
  // midpoint, against a table of its own there, over the separations in contact.
  for (int j = 0; j < intervals; ++j) {
    const double lnk = lnk_[std::size_t(j)] + 0.5 * step_, k = std::exp(lnk);
    const ContactTableKey at = scaled(key, k);
    const StatisticalContact direct(
        JacksonGreenAsperity(at.effective_modulus, at.yield_strength, at.poisson_ratio, at.summit_radius),
        at.summit_density, at.summit_sigma);
    const double low = direct.mean_summit_offset() - 5.0 * direct.summit_sigma();
    const double high = direct.contact_pressure_cutoff_gap();
    constexpr int kSamples = 97;
    for (int s = 0; s <= kSamples; ++s) {
      const double h = low + (high - low) * s / kSamples;
      const double exact = direct.pressure(h).value;
      if (!(exact > 0.0)) continue;
      error_bound_ = std::max(error_bound_, std::abs(pressure(h, k).value - exact) / exact);
    }
  }
}

ScaledContact::Stencil ScaledContact::stencil(double lnk) const {
  const int nodes = int(lnk_.size());
  // The (up to) four nodes nearest ln k: the interval holding it and one on each side,
  // shifted inward at the ends.
  const int interval = std::clamp(int(std::floor((lnk - lnk_.front()) / step_)), 0, std::max(0, nodes - 2));
  Stencil st;
  st.count = std::min(4, nodes);
  st.first = std::clamp(interval - 1, 0, nodes - st.count);
  for (int m = st.first; m < st.first + st.count; ++m) {
    // Lagrange's basis polynomial of node m over the stencil, and its slope in ln k.
    double w = 1.0, dw = 0.0;
    for (int o = st.first; o < st.first + st.count; ++o) {
      if (o == m) continue;
      const double denominator = lnk_[std::size_t(m)] - lnk_[std::size_t(o)];
      const double factor = (lnk - lnk_[std::size_t(o)]) / denominator;
      dw = dw * factor + w / denominator;
      w *= factor;
    }
    st.w[std::size_t(m - st.first)] = w;
    st.dw[std::size_t(m - st.first)] = dw;
  }
  return st;
}

ScaledContact::Reduced ScaledContact::reduced(double x, double lnk) const {
  const Stencil st = stencil(lnk);
  Reduced r;
  for (int m = st.first; m < st.first + st.count; ++m) {
    const double w = st.w[std::size_t(m - st.first)], dw = st.dw[std::size_t(m - st.first)];
    const double k = std::exp(lnk_[std::size_t(m)]);
    const ValueSlope p = tables_[std::size_t(m)]->pressure(k * x);
    if (!(p.value > 0.0)) {
      r.zero = true;
      return r;
    }
    const double g = std::log(p.value) - lnk_[std::size_t(m)], gx = k * p.slope / p.value;
    r.g += w * g;
    r.dx += w * gx;
    r.dlnk += dw * g;
  }
  return r;
}

// The count of summits in contact depends on their heights alone, which scale with k: it
// is the new population's at h/k. The real area is interpolated as the pressure is:
// ln A_r(h, k) = cubic in ln k of ln A_r,j(k_j·h/k), invariant for summits that do not yield.
StatisticalContact::SummitContacts ScaledContact::contacts(double h, double k) const {
  const double scale = std::clamp(k, k_low_, 1.0), x = h / scale;
  StatisticalContact::SummitContacts c;
  c.count = tables_.back()->contacts(x).count;
  const Stencil st = stencil(std::log(scale));
  double log_area = 0.0;
  for (int m = st.first; m < st.first + st.count; ++m) {
    const double area = tables_[std::size_t(m)]->contacts(std::exp(lnk_[std::size_t(m)]) * x).area_fraction;
    if (!(area > 0.0)) return {};
    log_area += st.w[std::size_t(m - st.first)] * std::log(area);
  }
  c.area_fraction = std::exp(log_area);
  return c;
}

ScaledContact::Pressure ScaledContact::pressure(double h, double k) const {
  // At the range's ends themselves the interpolant's own slope (a new face, k = 1, is
  // where running-in starts: its Rq's slope in the depth is finite there, running_in.h).
  const bool held = k > 1.0 || k < k_low_;
  const double scale = std::clamp(k, k_low_, 1.0), lnk = std::log(scale), x = h / scale;
  const Reduced r = reduced(x, lnk);
  if (r.zero) return {};
  const double p = scale * std::exp(r.g);
  // ln p = ln k + G(h/k, ln k): ∂/∂h = G_x/k; ∂/∂k = (1 − x·G_x + G_lnk)/k.
  return {p, p * r.dx / scale, held ? 0.0 : p * (1.0 - x * r.dx + r.dlnk) / scale};
}

std::shared_ptr<const ScaledContact> shared_scaled_contact(const ContactTableKey& key, double k_low) {
  // A few: a study's models share their scene's one population and run-in scale.
  constexpr std::size_t kKept = 4;
  static std::mutex guard;
  static std::vector<std::tuple<ContactTableKey, double, std::shared_ptr<const ScaledContact>>> kept;
  {
    const std::lock_guard lock(guard);
    for (const auto& [k, low, table] : kept)
      if (k == key && low == k_low) return table;
  }
  auto table = std::make_shared<const ScaledContact>(key, k_low);
  const std::lock_guard lock(guard);
  if (kept.size() == kKept) kept.erase(kept.begin());
  kept.emplace_back(key, k_low, table);
  return table;
}

}  // namespace twb
