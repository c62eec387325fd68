#include "twb/study/result_columns.h"

#include <set>

#include <nlohmann/json.hpp>

#include "model/reported_quantity.h"
#include "study/searches/distress_curve.h"
#include "study/searches/study_searches.h"
#include "twb/results/fields_table.h"
#include "twb/results/worn_washer.h"
#include "twb/scene/scene_loader.h"
#include "twb/study/study_outcome.h"

namespace twb {

namespace {

using Json = nlohmann::ordered_json;

// A table's columns from its fullest form (every optional column written): their names in
// file order, the count and text columns among them (the others are numbers), and the
// optional ones: those its plainest form (no parameter, no sliding film, no error bars)
// does not have.
Json columns(const ResultTable& fullest, const ResultTable& plainest) {
  std::set<std::string> always;
  for (const ResultColumn& c : plainest.columns()) always.insert(c.name);
  Json names = Json::array(), counts = Json::array(), texts = Json::array(), optional = Json::array();
  for (const ResultColumn& c : fullest.columns()) {
    names.push_back(c.name);
    if (c.kind == ResultColumn::Kind::count) counts.push_back(c.name);
    if (c.kind == ResultColumn::Kind::text) texts.push_back(c.name);
    if (!always.count(c.name)) optional.push_back(c.name);
  }
  return {{"columns", names}, {"counts", counts}, {"texts", texts}, {"optional", optional}};
}

}  // namespace

std::string result_columns_json() {
  const std::string parameter = "<parameter>", family = "<family>";
  // One row is enough for the states table to declare its error bars', flows' and effects'
  // columns (and for the trajectory its effects').
  SolvedState with_errors;
  with_errors.mesh_errors.assign(std::size(kMeshErrorQuantities), 0.0);
  with_errors.state.flows = FilmFlows{};
  for (const ReportedQuantity& q : effect_quantities()) with_errors.state.reported.push_back({std::string(q.column), 0.0});
  Json tables;
  tables["states"] = columns(states_table({with_errors}, {parameter}, true), states_table({}, {}, false));
  tables["distress"] = columns(distress_table({}, {parameter}, true), distress_table({}, {}, false));
  tables["sliding"] = columns(sliding_table({}), sliding_table({}));
  tables["fold_curve"] = columns(fold_curve_table({}, parameter, family), fold_curve_table({}, parameter));
  TrajectorySample reporting;
  reporting.state.reported = with_errors.state.reported;
  tables["trajectory"] =
      columns(trajectory_table({reporting}, {parameter}, true, true), trajectory_table({}, {}, false));
  tables["cycle_events"] = columns(cycle_events_table({}), cycle_events_table({}));
  tables["life"] = columns(life_table({}), life_table({}));
  tables["worn_profile"] = columns(worn_profile_table({}), worn_profile_table({}));
  // A bent washer's film declares the deflection, a column only the elastic washer writes.
  FilmFields bent{.film = 1, .sliding = true, .mesh = FilmMesh(1e-3, 2e-3, 2, 3), .gap = {}, .pressure = {},
                  .contact_pressure = {}, .film_temperature = {}, .surface_temperature = {}, .viscosity = {},
                  .washer_deflection = {}};
  for (std::vector<double>* f : {&bent.gap, &bent.pressure, &bent.contact_pressure, &bent.film_temperature,
                                 &bent.surface_temperature, &bent.viscosity, &bent.washer_deflection})
    f->assign(std::size_t(bent.mesh.node_count()), 0.0);
  tables["fields"] = columns(fields_table({bent}), fields_table({}));
  tables["sensitivity"] = columns(sensitivity_table({}), sensitivity_table({}));
  tables["reliability"] = columns(reliability_table({}), reliability_table({}));
  tables["design_point"] = columns(design_point_table({}), design_point_table({}));
  tables["calibration"] = columns(calibration_table({}), calibration_table({}));
  tables["calibration_correlation"] = columns(correlation_table({}), correlation_table({}));
  tables["calibration_points"] = columns(calibration_points_table({}), calibration_points_table({}));

  Json run_parameters = Json::array();
  for (MapParameter p : {MapParameter::friction_coefficient, MapParameter::gear_tilt, MapParameter::roughness,
                         MapParameter::groove_count, MapParameter::groove_width, MapParameter::groove_depth})
    run_parameters.push_back(parameter_column(p));
  run_parameters.push_back(kLifeTimeColumn);  // a life's states and searches, by its time
  Json curve_parameters = Json::array();
  for (CurveParameter p : {CurveParameter::speed, CurveParameter::friction_coefficient, CurveParameter::gear_tilt,
                           CurveParameter::ambient_temperature, CurveParameter::viscosity_scale,
                           CurveParameter::roughness})
    curve_parameters.push_back(fold_curve_column(p));
  Json sliding_films = Json::array();
  for (SlidingFilm f : {SlidingFilm::carrier_washer, SlidingFilm::washer_gear}) sliding_films.push_back(scene_name(f));
  Json failure_criteria = Json::array({"distress"});
  Json fold_kinds = Json::array();
  for (FoldKind k : {FoldKind::distress, FoldKind::recovery, FoldKind::cusp, FoldKind::turn}) {
    FoldCurveRow row;
    row.fold = k;
    fold_kinds.push_back(fold_name(row));
  }
  for (LimitKind kind : kFailureCriteria) {
    failure_criteria.push_back(limit_name(kind));
    fold_kinds.push_back(limit_name(kind));
  }

  Json out;
  out["about"] =
      "The columns of the CSV files twb writes, made by `twb columns` from the functions that write them; "
      "python/twb/plot reads the names from here. Do not edit: a test compares this file with `twb columns`.";
  out["tables"] = tables;
  out["run_parameters"] = run_parameters;
  out["curve_parameters"] = curve_parameters;
  out["sliding_films"] = sliding_films;
  out["branches"] = {branch_name(Branch::cool), branch_name(Branch::hot)};
  out["failure_criteria"] = failure_criteria;
  out["fold_kinds"] = fold_kinds;
  return out.dump(2) + "\n";
}

}  // namespace twb
