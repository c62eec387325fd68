// Where the model stops describing a real bearing, besides thermo-viscous distress: the
// limits a solved state can exceed, each with its value and its threshold, so that a
// converged state says what a user should not trust it for (docs/model.md, "Limits").
//  - oil_temperature: the washer's mean temperature, what the oil between the faces
//    settles to, above the oil's maximum working temperature (lubricant.max_temperature);
//  - oil_peak_temperature: the film temperature's peak (docs/physics.md section 7), located
//    between the nodes (section 8), above the oil's flash point (lubricant.flash_temperature);
//  - contact_pressure: the nominal asperity contact pressure where a film is tightest
//    above the softest face's hardness, 2.84·S_y (Tabor's, the largest H_G of docs/physics.md
//    section 4, eq [10]): the real contact area would exceed the nominal one, which the
//    statistical summit model cannot represent;
//  - film_below_statistics: h_min/σ below 0.5, the smallest gap Patir and Cheng fitted
//    their flow factors for and where most summits touch, against the statistical
//    model's assumption of sparse, independent contacts (only with contact or flow
//    factors on: classic Reynolds has no such limit);
//  - material_temperature:<body>: the body's hottest face above its material's limit
//    (materials.<body>.max_temperature; none by default);
//  - film_ratio: h_min/σ below the scene's least film parameter (limits.min_film_ratio;
//    none by default);
//  - pv: the sliding film's mean contact pressure times the sliding speed at the washer's
//    mean radius above the washer material's PV limit (materials.washer.pv_limit; none by
//    default);
//  - scuffing: the asperities' hottest contact temperature, the faces' plus Blok's flash
//    temperature, above the pair's critical scuffing temperature (limits.scuffing_temperature;
//    only with the contact model);
//  - modulus_data:<body>: the body's hottest face above the last temperature of its
//    material's modulus data (materials.<body>.modulus_by_temperature; only where given):
//    the modulus is held at the data's end there, not known (docs/physics.md section 23).
// oil_temperature, oil_peak_temperature, material_temperature, film_ratio, pv, scuffing and
// modulus_data are failure
// criteria (docs/physics.md section 8): the first load where one is crossed on the branch
// is a failure load beside thermo-viscous distress. contact_pressure and
// film_below_statistics say where the model stops holding.
#pragma once

#include <array>
#include <cstddef>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace twb {

enum class LimitKind {
  oil_temperature,
  oil_peak_temperature,
  contact_pressure,
  film_below_statistics,
  carrier_temperature,  // material_temperature:carrier
  washer_temperature,   // material_temperature:washer
  gear_temperature,     // material_temperature:gear
  film_ratio,
  pv,
  scuffing,
  carrier_modulus_data,  // modulus_data:carrier
  washer_modulus_data,   // modulus_data:washer
  gear_modulus_data,     // modulus_data:gear
};

// The limits whose crossing is a failure of the bearing (a failure criterion).
bool is_failure_criterion(LimitKind kind);
// The failure criteria in the order distress.csv lists their loads.
inline constexpr LimitKind kFailureCriteria[] = {LimitKind::oil_temperature, LimitKind::oil_peak_temperature,
                                                 LimitKind::carrier_temperature, LimitKind::washer_temperature,
                                                 LimitKind::gear_temperature, LimitKind::film_ratio, LimitKind::pv,
                                                 LimitKind::scuffing, LimitKind::carrier_modulus_data,
                                                 LimitKind::washer_modulus_data, LimitKind::gear_modulus_data};
// One value for each failure criterion, in kFailureCriteria's order: distress.csv's loads,
// a state's margins.
template <class T>
using PerCriterion = std::array<T, std::size(kFailureCriteria)>;
// A criterion's entry in a PerCriterion; none for a limit that is no failure criterion.
constexpr std::optional<std::size_t> criterion_index(LimitKind kind) {
  for (std::size_t c = 0; c < std::size(kFailureCriteria); ++c)
    if (kFailureCriteria[c] == kind) return c;
  return std::nullopt;
}

struct LimitExcess {
  LimitKind kind;
  double value = 0.0;  // SI: K, Pa, h_min/σ, or Pa m/s
  double limit = 0.0;
};

// "oil_temperature" and so on: the names in states.csv's limits column.
std::string_view limit_name(LimitKind kind);
// "the washer's mean temperature 721 degC is above the oil's maximum 150 degC".
std::string describe_limit(const LimitExcess& excess);
// The names of a state's limits joined by ';' (empty for none): states.csv's column.
std::string limit_names(const std::vector<LimitExcess>& limits);
// The same for the failure criteria among them only: states.csv's fails_by column.
std::string failure_names(const std::vector<LimitExcess>& limits);
// "the oil's peak temperature", "the washer's material temperature": for sentences.
std::string_view criterion_phrase(LimitKind kind);

}  // namespace twb
