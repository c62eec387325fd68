#include "twb/model/operating_limits.h"

#include "model/limit_thresholds.h"

#include <algorithm>

#include <fmt/format.h>

namespace twb {

namespace {
constexpr double kCelsius = 273.15;
// Tabor's hardness, about 2.8 S_y, and the largest H_G/S_y of eq [10] (small contacts;
// H_G falls as a contact grows): a nominal pressure above it cannot be carried by
// summits however many touch.
constexpr double kHardnessOverYield = 2.84;
}  // namespace

OperatingLimits OperatingLimits::of(const Scene& scene) {
  OperatingLimits l;
  l.max_oil_temperature = scene.lubricant.max_temperature;
  l.flash_temperature = scene.lubricant.flash_temperature;
  if (scene.effects.asperity_contact) {
    // Every face takes contact somewhere: the softest one yields first.
    const double softest = std::min({scene.carrier.material.yield_strength, scene.washer.material.yield_strength,
                                     scene.gear.material.yield_strength});
    l.hardness = kHardnessOverYield * softest;
  }
  l.statistical = scene.effects.asperity_contact || scene.effects.flow_factors;
  return l;
}

std::vector<LimitExcess> exceeded_limits(const LimitValues& v, const OperatingLimits& l) {
  std::vector<LimitExcess> out;
  if (v.thermal && v.washer_mean_temperature > l.max_oil_temperature)
    out.push_back({LimitKind::oil_temperature, v.washer_mean_temperature, l.max_oil_temperature});
  if (v.thermal && v.max_film_temperature > l.flash_temperature)
    out.push_back({LimitKind::flash_temperature, v.max_film_temperature, l.flash_temperature});
  if (l.hardness > 0 && v.max_contact_pressure > l.hardness)
    out.push_back({LimitKind::contact_pressure, v.max_contact_pressure, l.hardness});
  if (l.statistical && v.hmin_over_sigma < l.least_film)
    out.push_back({LimitKind::film_below_statistics, v.hmin_over_sigma, l.least_film});
  return out;
}

std::string_view limit_name(LimitKind kind) {
  switch (kind) {
    case LimitKind::oil_temperature: return "oil_temperature";
    case LimitKind::flash_temperature: return "flash_temperature";
    case LimitKind::contact_pressure: return "contact_pressure";
    case LimitKind::film_below_statistics: return "film_below_statistics";
  }
  return "?";
}

std::string describe_limit(const LimitExcess& e) {
  switch (e.kind) {
    case LimitKind::oil_temperature:
      return fmt::format("the washer's mean temperature {:.0f} degC is above the oil's maximum {:.0f} degC "
                         "(lubricant.max_temperature)",
                         e.value - kCelsius, e.limit - kCelsius);
    case LimitKind::flash_temperature:
      return fmt::format("the film (flash) temperature {:.0f} degC is above the oil's flash point {:.0f} degC "
                         "(lubricant.flash_temperature)",
                         e.value - kCelsius, e.limit - kCelsius);
    case LimitKind::contact_pressure:
      return fmt::format("the asperity contact pressure {:.3g} MPa is above the softer face's hardness {:.3g} MPa "
                         "(2.84 x yield strength): the statistical contact model no longer holds",
                         e.value * 1e-6, e.limit * 1e-6);
    case LimitKind::film_below_statistics:
      return fmt::format("h_min/sigma = {:.3g} is below {:.3g}, where the statistical contact and flow-factor "
                         "models hold",
                         e.value, e.limit);
  }
  return {};
}

std::string limit_names(const std::vector<LimitExcess>& limits) {
  std::string out;
  for (const LimitExcess& e : limits) {
    if (!out.empty()) out += ';';
    out += limit_name(e.kind);
  }
  return out;
}

}  // namespace twb
