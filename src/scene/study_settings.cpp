// A study's settings: each type's defaults, and what the machinery every type shares
// reads of them (twb/scene/study_settings.h).
#include "twb/scene/study_settings.h"

#include "twb/error_family.h"

namespace twb {

// Every type's settings that have error bars, speeds or axes hold them under these
// names (a load grid's speeds in its grid).

const ErrorBarSettings* Study::error_bars() const {
  return std::visit(
      [](const auto& s) -> const ErrorBarSettings* {
        if constexpr (requires { s.error_bars; })
          return &s.error_bars;
        else
          return nullptr;
      },
      settings);
}

std::span<const double> Study::speeds() const {
  return std::visit(
      [](const auto& s) -> std::span<const double> {
        if constexpr (requires { s.grid.speeds; })
          return s.grid.speeds;
        else if constexpr (requires { s.speeds; })
          return s.speeds;
        else
          return {};
      },
      settings);
}

namespace {

// The axes of `settings` (const or not), as the study's axes() give them.
template <class Settings>
auto axes_of(Settings& settings) {
  using Axis = std::conditional_t<std::is_const_v<Settings>, const MapAxis, MapAxis>;
  return std::visit(
      [](auto& s) -> std::span<Axis> {
        if constexpr (requires { s.axes; })
          return s.axes;
        else
          return {};
      },
      settings);
}

}  // namespace

std::span<const MapAxis> Study::axes() const { return axes_of(settings); }

std::span<MapAxis> Study::axes() { return axes_of(settings); }

StudySettings default_settings(StudyType type) {
  switch (type) {
    case StudyType::point: return PointSettings{};
    case StudyType::load_sweep: return LoadSweepSettings{};
    case StudyType::distress_map: return DistressMapSettings{};
    case StudyType::transient: return LoadStepSettings{};
    case StudyType::sliding_choice: return SlidingChoiceSettings{};
    case StudyType::distress_curve: return DistressCurveSettings{};
    case StudyType::sensitivity: return SensitivitySettings{};
    case StudyType::reliability: return ReliabilitySettings{};
    case StudyType::calibration: return CalibrationSettings{};
    case StudyType::duty_cycle: return DutyCycleSettings{};
    case StudyType::life: return LifeSettings{};
  }
  throw InternalError("default_settings: a study type without its settings");
}

}  // namespace twb
