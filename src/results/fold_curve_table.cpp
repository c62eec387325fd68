#include "twb/results/fold_curve_table.h"

#include "result_cells.h"

namespace twb {

std::string fold_curve_csv(const std::vector<FoldCurveRow>& rows, const std::string& parameter_column,
                           const std::string& family_column) {
  std::string out = cells::run_header(family_column, false) + parameter_column +
                    ",W_fold_N,fold,T_mean_C,T_max_C,hmin_over_sigma,contact_share,f_eff\n";
  const double offset = parameter_column == "ambient_C" ? cells::kelvin_offset : 0.0;
  for (const FoldCurveRow& r : rows) {
    const BearingState& s = r.state;
    out += cells::run_cells(family_column, false, r.member, {});
    out += fmt::format("{},{},{},{},{},{},{},{}\n", cells::number(r.parameter - offset, "parameter"),
                       cells::number(s.load, "W_fold"), r.fold,
                       cells::number(s.washer_mean_temperature - cells::kelvin_offset, "T_mean"),
                       cells::number(s.max_film_temperature - cells::kelvin_offset, "T_max"),
                       cells::number(s.hmin_over_sigma, "hmin_over_sigma"),
                       cells::number(s.contact_share, "contact_share"), cells::number(s.f_eff, "f_eff"));
  }
  return out;
}

}  // namespace twb
