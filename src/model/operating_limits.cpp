#include "twb/model/operating_limits.h"

#include "model/limit_thresholds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

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
  l.flash_point = scene.lubricant.flash_temperature;
  if (scene.effects.asperity_contact) {
    // Every face takes contact somewhere: the softest one yields first.
    const double softest = std::min({scene.carrier.material.yield_strength, scene.washer.material.yield_strength,
                                     scene.gear.material.yield_strength});
    l.hardness = kHardnessOverYield * softest;
  }
  l.statistical = scene.effects.asperity_contact || scene.effects.flow_factors;
  l.material_temperature = {scene.carrier.material.max_temperature, scene.washer.material.max_temperature,
                            scene.gear.material.max_temperature};
  const Material* bodies[] = {&scene.carrier.material, &scene.washer.material, &scene.gear.material};
  for (std::size_t b = 0; b < 3; ++b)
    if (!bodies[b]->modulus_by_temperature.empty())
      l.modulus_data_end[b] = bodies[b]->modulus_by_temperature.back().temperature;
  l.min_film_ratio = scene.limits.min_film_ratio;
  l.pv_limit = scene.washer.material.pv_limit;
  if (scene.effects.asperity_contact) l.scuffing_temperature = scene.limits.scuffing_temperature;
  const double ri = scene.washer.inner_radius, ro = scene.washer.outer_radius;
  l.washer_area = std::numbers::pi * (ro * ro - ri * ri);
  l.mean_radius = 0.5 * (ri + ro);
  return l;
}

double LimitValues::pv(const OperatingLimits& limits) const {
  return contact_force / limits.washer_area * std::abs(speed) * limits.mean_radius;
}

LimitValues LimitValues::of(const BearingState& s, bool thermal) {
  return {s.washer_mean_temperature,
          s.oil_peak_temperature,
          s.max_contact_pressure,
          s.hmin_over_sigma,
          thermal,
          {s.carrier_max_temperature, s.washer_max_temperature, s.gear_max_temperature},
          s.contact_force,
          s.speed,
          s.contact_temperature};
}

namespace {
constexpr std::array kMaterialTemperature{LimitKind::carrier_temperature, LimitKind::washer_temperature,
                                          LimitKind::gear_temperature};
constexpr std::array kModulusData{LimitKind::carrier_modulus_data, LimitKind::washer_modulus_data,
                                  LimitKind::gear_modulus_data};
// The body of a criterion on a body's hottest face: 0 carrier, 1 washer, 2 gear.
std::optional<std::size_t> body_of(LimitKind kind) {
  for (std::size_t b = 0; b < 3; ++b)
    if (kind == kMaterialTemperature[b] || kind == kModulusData[b]) return b;
  return std::nullopt;
}
// The threshold of a criterion on a body's hottest face, where the scene gives one.
const std::optional<double>& body_threshold(LimitKind kind, std::size_t body, const OperatingLimits& l) {
  return std::find(kModulusData.begin(), kModulusData.end(), kind) != kModulusData.end() ? l.modulus_data_end[body]
                                                                                          : l.material_temperature[body];
}
}  // namespace

bool is_failure_criterion(LimitKind kind) {
  return kind != LimitKind::contact_pressure && kind != LimitKind::film_below_statistics;
}

std::optional<double> failure_margin(LimitKind kind, const LimitValues& v, const OperatingLimits& l) {
  if (const auto body = body_of(kind)) {
    const std::optional<double>& threshold = body_threshold(kind, *body, l);
    if (!v.thermal || !threshold) return std::nullopt;
    return *threshold - v.body_temperature[*body];
  }
  switch (kind) {
    case LimitKind::oil_temperature:
      if (!v.thermal) return std::nullopt;
      return l.max_oil_temperature - v.washer_mean_temperature;
    case LimitKind::oil_peak_temperature:
      if (!v.thermal) return std::nullopt;
      return l.flash_point - v.oil_peak_temperature;
    case LimitKind::film_ratio:
      if (!l.min_film_ratio) return std::nullopt;
      return v.hmin_over_sigma - *l.min_film_ratio;
    case LimitKind::pv:
      if (!l.pv_limit) return std::nullopt;
      return *l.pv_limit - v.pv(l);
    case LimitKind::scuffing:
      if (!l.scuffing_temperature || !v.contact_temperature) return std::nullopt;
      return *l.scuffing_temperature - *v.contact_temperature;
    default:
      return std::nullopt;
  }
}

bool criterion_applies(LimitKind kind, const OperatingLimits& limits, bool thermal) {
  LimitValues any;
  any.thermal = thermal;
  any.contact_temperature = 0.0;  // every state has one where the contact model is on
  return failure_margin(kind, any, limits).has_value();
}

std::vector<LimitExcess> exceeded_limits(const LimitValues& v, const OperatingLimits& l) {
  std::vector<LimitExcess> out;
  if (v.thermal && v.washer_mean_temperature > l.max_oil_temperature)
    out.push_back({LimitKind::oil_temperature, v.washer_mean_temperature, l.max_oil_temperature});
  if (v.thermal && v.oil_peak_temperature > l.flash_point)
    out.push_back({LimitKind::oil_peak_temperature, v.oil_peak_temperature, l.flash_point});
  if (l.hardness > 0 && v.max_contact_pressure > l.hardness)
    out.push_back({LimitKind::contact_pressure, v.max_contact_pressure, l.hardness});
  if (l.statistical && v.hmin_over_sigma < l.least_film)
    out.push_back({LimitKind::film_below_statistics, v.hmin_over_sigma, l.least_film});
  for (std::size_t b = 0; b < 3; ++b)
    if (v.thermal && l.material_temperature[b] && v.body_temperature[b] > *l.material_temperature[b])
      out.push_back({kMaterialTemperature[b], v.body_temperature[b], *l.material_temperature[b]});
  if (l.min_film_ratio && v.hmin_over_sigma < *l.min_film_ratio)
    out.push_back({LimitKind::film_ratio, v.hmin_over_sigma, *l.min_film_ratio});
  if (l.pv_limit && v.pv(l) > *l.pv_limit) out.push_back({LimitKind::pv, v.pv(l), *l.pv_limit});
  if (l.scuffing_temperature && v.contact_temperature && *v.contact_temperature > *l.scuffing_temperature)
    out.push_back({LimitKind::scuffing, *v.contact_temperature, *l.scuffing_temperature});
  for (std::size_t b = 0; b < 3; ++b)
    if (v.thermal && l.modulus_data_end[b] && v.body_temperature[b] > *l.modulus_data_end[b])
      out.push_back({kModulusData[b], v.body_temperature[b], *l.modulus_data_end[b]});
  return out;
}

std::string_view limit_name(LimitKind kind) {
  switch (kind) {
    case LimitKind::oil_temperature: return "oil_temperature";
    case LimitKind::oil_peak_temperature: return "oil_peak_temperature";
    case LimitKind::contact_pressure: return "contact_pressure";
    case LimitKind::film_below_statistics: return "film_below_statistics";
    case LimitKind::carrier_temperature: return "material_temperature:carrier";
    case LimitKind::washer_temperature: return "material_temperature:washer";
    case LimitKind::gear_temperature: return "material_temperature:gear";
    case LimitKind::film_ratio: return "film_ratio";
    case LimitKind::pv: return "pv";
    case LimitKind::scuffing: return "scuffing";
    case LimitKind::carrier_modulus_data: return "modulus_data:carrier";
    case LimitKind::washer_modulus_data: return "modulus_data:washer";
    case LimitKind::gear_modulus_data: return "modulus_data:gear";
  }
  return "?";
}

std::string_view criterion_phrase(LimitKind kind) {
  switch (kind) {
    case LimitKind::oil_temperature: return "the oil's maximum temperature";
    case LimitKind::oil_peak_temperature: return "the oil's peak temperature";
    case LimitKind::contact_pressure: return "the contact pressure";
    case LimitKind::film_below_statistics: return "the statistical models' least film";
    case LimitKind::carrier_temperature: return "the carrier's material temperature";
    case LimitKind::washer_temperature: return "the washer's material temperature";
    case LimitKind::gear_temperature: return "the gear's material temperature";
    case LimitKind::film_ratio: return "the least film ratio";
    case LimitKind::pv: return "the washer's PV limit";
    case LimitKind::scuffing: return "scuffing";
    case LimitKind::carrier_modulus_data: return "the carrier's modulus data";
    case LimitKind::washer_modulus_data: return "the washer's modulus data";
    case LimitKind::gear_modulus_data: return "the gear's modulus data";
  }
  return "?";
}

std::string describe_limit(const LimitExcess& e) {
  switch (e.kind) {
    case LimitKind::oil_temperature:
      return fmt::format("the washer's mean temperature {:.0f} degC is above the oil's maximum {:.0f} degC "
                         "(lubricant.max_temperature)",
                         e.value - kCelsius, e.limit - kCelsius);
    case LimitKind::oil_peak_temperature:
      return fmt::format("the oil's peak temperature {:.0f} degC is above its flash point {:.0f} degC "
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
    case LimitKind::carrier_temperature:
    case LimitKind::washer_temperature:
    case LimitKind::gear_temperature:
      return fmt::format("the {}'s hottest face {:.0f} degC is above its material's limit {:.0f} degC "
                         "(materials.{}.max_temperature)",
                         limit_name(e.kind).substr(21), e.value - kCelsius, e.limit - kCelsius,
                         limit_name(e.kind).substr(21));
    case LimitKind::film_ratio:
      return fmt::format("h_min/sigma = {:.3g} is below the least film ratio {:.3g} (limits.min_film_ratio)",
                         e.value, e.limit);
    case LimitKind::pv:
      return fmt::format("the sliding face's PV {:.3g} MPa m/s (mean contact pressure times sliding speed) is above "
                         "the washer's limit {:.3g} MPa m/s (materials.washer.pv_limit)",
                         1e-6 * e.value, 1e-6 * e.limit);
    case LimitKind::scuffing:
      return fmt::format("the asperities' contact temperature {:.0f} degC (the faces' plus Blok's flash temperature) "
                         "is above the pair's scuffing temperature {:.0f} degC (limits.scuffing_temperature)",
                         e.value - kCelsius, e.limit - kCelsius);
    case LimitKind::carrier_modulus_data:
    case LimitKind::washer_modulus_data:
    case LimitKind::gear_modulus_data:
      return fmt::format("the {}'s hottest face {:.0f} degC is beyond its material's modulus data, which end at "
                         "{:.0f} degC (materials.{}.modulus_by_temperature): the modulus there is the data's last, "
                         "not known",
                         limit_name(e.kind).substr(13), e.value - kCelsius, e.limit - kCelsius,
                         limit_name(e.kind).substr(13));
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

std::string failure_names(const std::vector<LimitExcess>& limits) {
  std::vector<LimitExcess> failures;
  for (const LimitExcess& e : limits)
    if (is_failure_criterion(e.kind)) failures.push_back(e);
  return limit_names(failures);
}

}  // namespace twb
