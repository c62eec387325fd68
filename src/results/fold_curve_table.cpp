#include "twb/results/fold_curve_table.h"

#include "result_cells.h"

namespace twb {

using cells::kelvin_offset;

std::string fold_name(const FoldCurveRow& row) {
  switch (row.fold) {
    case FoldKind::distress: return "distress";
    case FoldKind::recovery: return "recovery";
    case FoldKind::cusp: return "cusp";
    case FoldKind::turn: return "turn";
    case FoldKind::limit: return std::string(limit_name(row.limit));
  }
  return "?";
}

ResultTable fold_curve_table(const std::vector<FoldCurveRow>& rows, const std::string& parameter_column,
                             const std::string& family_column) {
  ResultTable t;
  const cells::RunColumns family(t, family_column.empty() ? std::vector<std::string>{} : std::vector{family_column},
                                 false);
  const auto parameter = t.number(parameter_column), w_fold = t.number("W_fold_N"), fold = t.text("fold"),
             t_mean = t.number("T_mean_C"), t_max = t.number("T_max_C"), hmin = t.number("hmin_over_sigma"),
             contact = t.number("contact_share"), f_eff = t.number("f_eff"), fine = t.number("W_fold_fine_N"),
             extrapolated = t.number("W_fold_extrapolated_N"), error = t.number("W_fold_error_N");
  const cells::ConvergenceColumns convergence(t, "W_fold", true);
  const double offset = parameter_column == "ambient_C" ? kelvin_offset : 0.0;
  for (const FoldCurveRow& r : rows) {
    const BearingState& s = r.state;
    family.put(t, r.member ? std::vector<double>{*r.member} : std::vector<double>{}, {});
    t.put_number(parameter, r.parameter - offset);
    t.put_number(w_fold, s.load);
    t.put_text(fold, fold_name(r));
    t.put_number(t_mean, s.washer_mean_temperature - kelvin_offset);
    t.put_number(t_max, s.max_film_temperature - kelvin_offset);
    t.put_number(hmin, s.hmin_over_sigma);
    t.put_number(contact, s.contact_share);
    t.put_number(f_eff, s.f_eff);
    t.put_number(fine, r.fine_load);
    t.put_number(extrapolated, r.extrapolated_load);
    t.put_number(error, r.discretization_error);
    convergence.put(t, r.convergence);
  }
  return t;
}

std::string fold_curve_csv(const std::vector<FoldCurveRow>& rows, const std::string& parameter_column,
                           const std::string& family_column) {
  return fold_curve_table(rows, parameter_column, family_column).csv();
}

}  // namespace twb
