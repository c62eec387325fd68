#include "scene/quantity.h"

#include <udunits2.h>

#include <array>
#include <charconv>
#include <cmath>
#include <memory>
#include <mutex>
#include <utility>

#include <fmt/format.h>

namespace twb {
namespace {

struct FreeUnit {
  void operator()(ut_unit* unit) const { ut_free(unit); }
};
struct FreeConverter {
  void operator()(cv_converter* converter) const { cv_free(converter); }
};
using UnitPtr = std::unique_ptr<ut_unit, FreeUnit>;
using ConverterPtr = std::unique_ptr<cv_converter, FreeConverter>;

// The unit database, read once per process. udunits2 keeps parser state in globals, so
// every call into it goes through this object's lock.
class UnitSystem {
 public:
  static UnitSystem& instance() {
    static UnitSystem system;
    return system;
  }

  std::unique_lock<std::mutex> lock() { return std::unique_lock(mutex_); }

  const ut_unit* one() const { return ut_get_dimensionless_unit_one(system_.get()); }

  // nullptr when the text is not a unit udunits2 knows.
  UnitPtr parse(std::string_view text) const {
    const std::string owned(text);
    return UnitPtr(ut_parse(system_.get(), owned.c_str(), UT_UTF8));
  }

 private:
  UnitSystem() {
    // The stock database redefines a few symbols on purpose and udunits2 prints a
    // warning for each; nothing of that is useful to a scene's author.
    ut_set_error_message_handler(ut_ignore);
    system_.reset(ut_read_xml(TWB_UDUNITS2_XML));
    if (!system_)
      throw std::runtime_error(
          fmt::format("cannot read the udunits2 unit database '{}'", TWB_UDUNITS2_XML));
  }

  struct FreeSystem {
    void operator()(ut_system* system) const { ut_free_system(system); }
  };
  std::unique_ptr<ut_system, FreeSystem> system_;
  std::mutex mutex_;
};

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

bool is_yaml_non_finite(std::string_view number) {
  // YAML 1.2 spells infinity and NaN with a leading dot.
  for (std::string_view spelling : {".inf", "+.inf", "-.inf", ".Inf", "+.Inf", "-.Inf", ".INF",
                                    "+.INF", "-.INF", ".nan", ".NaN", ".NAN"})
    if (number == spelling) return true;
  return false;
}

std::string no_number_message(std::string_view text, const SiUnit& expected) {
  return fmt::format(
      "'{}' is not a number; expected {}: a number, optionally followed by a space and "
      "a unit convertible to {}, e.g. '{}'",
      text, expected.kind, expected.symbol, expected.example);
}

// Dimensions a scene author is likely to write by mistake, named for the message that
// says which one they wrote. Order matters where udunits2 cannot tell two apart
// (energy and torque): the first match wins.
struct NamedDimension {
  std::string_view name;
  std::string_view unit;
};
constexpr std::array<NamedDimension, 19> kNamedDimensions{{
    {"dimensionless", "1"},
    {"length", "m"},
    {"area", "m^2"},
    {"volume", "m^3"},
    {"time", "s"},
    {"mass", "kg"},
    {"temperature", "K"},
    {"angular speed (or frequency)", "1/s"},
    {"velocity", "m/s"},
    {"force", "N"},
    {"pressure", "Pa"},
    {"energy", "J"},
    {"power", "W"},
    {"thermal conductivity", "W/(m K)"},
    {"density", "kg/m^3"},
    {"specific heat", "J/(kg K)"},
    {"dynamic viscosity", "Pa s"},
    {"number per unit area", "1/m^2"},
    {"electric current", "A"},
}};

// udunits2 also converts between reciprocal units (s and Hz, m^2 and 1/m^2), which in a
// scene file would turn "10 s" into an angular speed of 0.1 rad/s. Two units have the
// same dimension only if their quotient is dimensionless.
bool same_dimension(UnitSystem& system, const ut_unit* a, const ut_unit* b) {
  if (!ut_are_convertible(a, b)) return false;
  const UnitPtr quotient(ut_divide(a, b));
  return quotient && ut_are_convertible(quotient.get(), system.one());
}

std::string dimension_of(UnitSystem& system, const ut_unit* unit) {
  for (const auto& dimension : kNamedDimensions) {
    const UnitPtr reference = system.parse(dimension.unit);
    if (reference && same_dimension(system, unit, reference.get())) return std::string(dimension.name);
  }
  return {};
}

// Spellings people type that udunits2 does not know, accepted as what they mean: the
// centipoise of oil data sheets, and "deg" for degrees of angle.
std::string_view accepted_spelling(std::string_view unit) {
  if (unit == "cP" || unit == "cp") return "mPa s";
  if (unit == "deg" || unit == "degrees") return "degree";
  return unit;
}

// What a unit that fails probably meant, for the message ("" when nothing comes to mind).
std::string spelling_hint(std::string_view unit, const SiUnit& expected) {
  if (expected.symbol == "K" && (unit == "C" || unit == "F"))
    return fmt::format(" (did you mean 'deg{0}'? '{0}' is the {1})", unit, unit == "C" ? "coulomb" : "farad");
  if (unit == "cSt" || unit == "St")
    return " (a kinematic viscosity; give the dynamic one, its value times the density: 1 cSt of a "
           "850 kg/m^3 oil is 0.85 mPa s)";
  if (unit == "rev/min" || unit == "RPM") return " (write 'rpm')";
  return {};
}

}  // namespace

double to_si(std::string_view text, const SiUnit& expected) {
  const std::string_view whole = trim(text);
  const auto split = whole.find_first_of(" \t");
  std::string_view number = whole.substr(0, split);
  const std::string_view written_unit =
      split == std::string_view::npos ? std::string_view{} : trim(whole.substr(split));
  const std::string_view unit_text = accepted_spelling(written_unit);

  if (is_yaml_non_finite(number))
    throw QuantityError(fmt::format("'{}' is not a finite number", whole));
  if (!number.empty() && number.front() == '+') number.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
  if (number.empty() || error == std::errc::invalid_argument ||
      end != number.data() + number.size())
    throw QuantityError(no_number_message(whole, expected));
  if (error == std::errc::result_out_of_range || !std::isfinite(value))
    throw QuantityError(fmt::format("'{}' is not a finite number", whole));
  if (unit_text.empty()) return value;

  UnitSystem& system = UnitSystem::instance();
  const auto guard = system.lock();
  const UnitPtr given = system.parse(unit_text);
  if (!given)
    throw QuantityError(fmt::format("'{}' has an unknown unit '{}'{}; expected {} convertible to {}, e.g. '{}'",
                                    whole, written_unit, spelling_hint(written_unit, expected), expected.kind,
                                    expected.symbol, expected.example));
  const UnitPtr target = system.parse(expected.symbol);
  if (!target)
    throw std::logic_error(fmt::format("udunits2 does not know the SI unit '{}'", expected.symbol));
  if (!same_dimension(system, given.get(), target.get())) {
    const std::string dimension = dimension_of(system, given.get());
    const std::string what = dimension.empty() ? fmt::format("has units '{}'", written_unit)
                             : dimension == "dimensionless"
                                 ? std::string("is dimensionless")
                                 : fmt::format("has the dimension of {}", dimension);
    throw QuantityError(fmt::format("'{}' {}{}, expected {} convertible to {}", whole, what,
                                    spelling_hint(written_unit, expected), expected.kind, expected.symbol));
  }
  const ConverterPtr converter(ut_get_converter(given.get(), target.get()));
  if (!converter)
    throw std::logic_error(fmt::format("udunits2 has no converter from '{}' to '{}'", unit_text,
                                       expected.symbol));
  const double converted = cv_convert_double(converter.get(), value);
  if (!std::isfinite(converted))
    throw QuantityError(fmt::format("'{}' is not a finite number in {}", whole, expected.symbol));
  return converted;
}

std::string dimension_name(std::string_view unit) {
  UnitSystem& system = UnitSystem::instance();
  const auto guard = system.lock();
  const UnitPtr parsed = system.parse(trim(unit));
  return parsed ? dimension_of(system, parsed.get()) : std::string{};
}

}  // namespace twb
