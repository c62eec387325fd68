#include "scene/input_distribution.h"

#include <cmath>

#include <boost/math/distributions/normal.hpp>
#include <fmt/format.h>

namespace twb {

namespace {

const boost::math::normal kStandard;

// Φ(u) and its complement, each accurate in its own tail.
double lower_tail(double u) { return boost::math::cdf(kStandard, u); }
double upper_tail(double u) { return boost::math::cdf(boost::math::complement(kStandard, u)); }
double density(double u) { return boost::math::pdf(kStandard, u); }

// The lognormal's parameters from the input's own mean m and sd s:
// σ² = ln(1 + s²/m²), μ = ln m − σ²/2.
double log_sd(const UncertainInput& in) { return std::sqrt(std::log1p((in.sd / in.mean) * (in.sd / in.mean))); }
double log_mean(const UncertainInput& in) { return std::log(in.mean) - 0.5 * log_sd(in) * log_sd(in); }

// A truncated normal's standardized bounds.
struct Cut {
  double a, b;
};
Cut cut(const UncertainInput& in) { return {(in.lower - in.mean) / in.sd, (in.upper - in.mean) / in.sd}; }

// Which tail the truncated law's masses are kept in: the upper one where the cut lies
// above the mean, or where it straddles it and u > 0; the lower one otherwise. Both are
// exact where small (a cut at 8 to 10 sd keeps its mass).
bool upper(const Cut& c, double u) { return c.a > 0.0 || (c.b > 0.0 && u > 0.0); }

// The cut's mass, in the tail chosen.
double mass(const Cut& c, double u) {
  return upper(c, u) ? upper_tail(c.a) - upper_tail(c.b) : lower_tail(c.b) - lower_tail(c.a);
}

// z of the truncated law at u: the mass Φ(u) of the standard normal mapped onto the
// mass between the bounds.
double truncated_z(const UncertainInput& in, double u) {
  const Cut c = cut(in);
  if (!upper(c, u)) return boost::math::quantile(kStandard, lower_tail(c.a) + lower_tail(u) * mass(c, u));
  return boost::math::quantile(boost::math::complement(kStandard, upper_tail(c.b) + upper_tail(u) * mass(c, u)));
}

}  // namespace

double input_at(const UncertainInput& in, double u) {
  switch (in.distribution) {
    case InputDistribution::normal:
      return in.mean + in.sd * u;
    case InputDistribution::lognormal:
      return std::exp(log_mean(in) + log_sd(in) * u);
    case InputDistribution::uniform:
      return u <= 0.0 ? in.lower + (in.upper - in.lower) * lower_tail(u) : in.upper - (in.upper - in.lower) * upper_tail(u);
    case InputDistribution::truncated_normal:
      return in.mean + in.sd * truncated_z(in, u);
  }
  return in.mean;
}

double input_slope(const UncertainInput& in, double u) {
  switch (in.distribution) {
    case InputDistribution::normal:
      return in.sd;
    case InputDistribution::lognormal:
      return log_sd(in) * input_at(in, u);
    case InputDistribution::uniform:
      return (in.upper - in.lower) * density(u);
    case InputDistribution::truncated_normal:
      // dx/du = sd·(Φ(b) − Φ(a))·φ(u)/φ(z)
      return in.sd * mass(cut(in), u) * density(u) / density(truncated_z(in, u));
  }
  return in.sd;
}

std::string describe(const UncertainInput& in) {
  // "0.0005 rad"; a pure number without its "1".
  const auto q = [&](double v) { return in.unit == "1" ? fmt::format("{:.6g}", v) : fmt::format("{:.6g} {}", v, in.unit); };
  switch (in.distribution) {
    case InputDistribution::normal:
      return fmt::format("normal(mean {}, sd {})", q(in.mean), q(in.sd));
    case InputDistribution::lognormal:
      return fmt::format("lognormal(mean {}, sd {})", q(in.mean), q(in.sd));
    case InputDistribution::uniform:
      return fmt::format("uniform({} to {})", q(in.lower), q(in.upper));
    case InputDistribution::truncated_normal:
      return fmt::format("truncated_normal(mean {}, sd {}, {} to {})", q(in.mean), q(in.sd), q(in.lower), q(in.upper));
  }
  return in.path;
}

}  // namespace twb
