// study type distress_curve: the fold continued in one parameter, for the scene's
// bearing or each member of a family.
#include <fmt/format.h>

#include "scene/physical_bounds.h"
#include "scene/scene_names.h"
#include "scene/studies/study_keys.h"
#include "scene/studies/study_section.h"

namespace twb::scene_io {
namespace {

constexpr std::string_view kKeys[] = {"type",     "parameter",     "from",   "to",
                                      "load_start", "load_end",    "bracket_width", "family",
                                      "error_estimate", "tolerance"};

// distress_curve: `parameter: speed`, `from`, `to` in its unit, the first fold's load
// range optional.
void read_fold_curve(const MapReader& study, Scene& out) {
  DistressCurveSettings& s = std::get<DistressCurveSettings>(out.study.settings);
  const Node name =
      study.get("parameter", "speed, friction_coefficient, gear_tilt, ambient_temperature, viscosity_scale or roughness");
  s.curve_parameter = kCurveParameters.values[name.choice(kCurveParameters.names)];
  if (s.curve_parameter == CurveParameter::friction_coefficient && out.friction.law != FrictionLaw::constant)
    name.fail(fmt::format("{}: friction_coefficient varies the constant friction law's coefficient; "
                          "set friction.law: constant",
                          name.path()));
  auto value = [&](const char* key) {
    switch (s.curve_parameter) {
      case CurveParameter::speed:
        return study.quantity(key, si::angular_speed, bounds::speed);
      case CurveParameter::friction_coefficient:
        return study.quantity(key, si::dimensionless, bounds::friction_coefficient);
      case CurveParameter::gear_tilt:
        return study.quantity(key, si::angle, bounds::tilt);
      case CurveParameter::ambient_temperature:
        return study.quantity(key, si::temperature, bounds::roelands_temperature);
      case CurveParameter::viscosity_scale:
        return study.quantity(key, si::dimensionless, bounds::viscosity_scale);
      case CurveParameter::roughness:
        return study.quantity(key, si::length, bounds::roughness);
    }
    return 0.0;
  };
  s.from = value("from");
  s.to = value("to");
  if (s.curve_parameter == CurveParameter::speed)
    out.study.speeds_in_rpm = given_in_rpm(study.get("from", "")) && given_in_rpm(study.get("to", ""));
  if (s.to == s.from) {
    const Node to = study.get("to", "");
    to.fail(fmt::format("{}: '{}' must differ from 'from': the curve needs a range", to.path(), to.yaml().Scalar()));
  }
  // The first fold is searched between these loads (defaults: a fifth and four times
  // operating.load).
  LoadRange& loads = s.search.loads;
  loads.start = study.quantity("load_start", si::force, bounds::load, 0.2 * out.operating.load);
  loads.end = study.quantity("load_end", si::force, bounds::load, 4.0 * out.operating.load);
  if (loads.end <= loads.start) {
    const Node node = study.has("load_end") ? study.get("load_end", "") : study.get("load_start", "");
    node.fail(fmt::format("{}: load_end must be greater than load_start (here {:.6g} N and {:.6g} N)", node.path(),
                          loads.end, loads.start));
  }
  s.search.bracket_width = read_bracket_width(study, s.search.bracket_width);
}

void read(const MapReader& study, Scene& out) {
  read_fold_curve(study, out);
  DistressCurveSettings& s = std::get<DistressCurveSettings>(out.study.settings);
  s.error_bars.estimate = read_choice(study, "error_estimate", kErrorEstimates, s.error_bars.estimate);
  read_tolerance(study, s.error_bars);
  refuse_every_state(study, s.error_bars, "distress_curve");
  read_map_axes(study, s.axes, out, "family");
}

void write(SceneText& w, const Study& study) {
  const DistressCurveSettings& s = std::get<DistressCurveSettings>(study.settings);
  write_load_range(w, s.search.loads);
  write_error_estimate(w, s.error_bars);
  write_tolerance(w, s.error_bars);
  const char* unit = s.curve_parameter == CurveParameter::speed                  ? "rad/s"
                     : s.curve_parameter == CurveParameter::gear_tilt            ? "rad"
                     : s.curve_parameter == CurveParameter::roughness            ? "m"
                     : s.curve_parameter == CurveParameter::ambient_temperature ? "K"
                                                                                 : "1";
  w.entry(1, "parameter", std::string(kCurveParameters.name(s.curve_parameter)));
  w.entry(1, "from", quantity(s.from, unit));
  w.entry(1, "to", quantity(s.to, unit));
  w.entry(1, "bracket_width", quantity(s.search.bracket_width, "1"));
  write_axes(w, s.axes, "family");
}

}  // namespace

extern const StudySection kDistressCurveKeys{.keys = kKeys, .read = read, .write = write};

}  // namespace twb::scene_io
