// twb._twb: the compiled half of the Python module (python/twb/__init__.py is the other),
// written against the public API alone (docs/api.md). It loads scenes with the loader's
// own validation, runs studies with the GIL released, and hands every results table
// over as the columns the CSV files are written from (study_tables), so that Python
// sees the numbers twb run writes, unrounded.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "twb/twb.h"

namespace py = pybind11;

namespace {

// A results table as a dict of columns: numbers as float64 arrays (NaN where a value does
// not exist, an empty CSV cell), counts as int64 arrays, texts as lists of str; and the
// printf format each column is written with in the CSV file.
py::tuple table_columns(const twb::ResultTable& table) {
  py::dict columns, formats;
  for (const twb::ResultColumn& c : table.columns()) {
    switch (c.kind) {
      case twb::ResultColumn::Kind::number: {
        columns[py::str(c.name)] = py::array_t<double>(py::ssize_t(c.numbers.size()), c.numbers.data());
        const char* f = c.style == twb::ResultColumn::Style::scientific ? "%.3e"
                        : c.style == twb::ResultColumn::Style::fixed    ? "%.3f"
                                                                         : "%.10g";
        formats[py::str(c.name)] = f;
        break;
      }
      case twb::ResultColumn::Kind::count: {
        py::array_t<long long> a(py::ssize_t(c.numbers.size()));
        auto w = a.mutable_unchecked<1>();
        for (std::size_t k = 0; k < c.numbers.size(); ++k) w(py::ssize_t(k)) = static_cast<long long>(c.numbers[k]);
        columns[py::str(c.name)] = a;
        formats[py::str(c.name)] = "%d";
        break;
      }
      case twb::ResultColumn::Kind::text:
        columns[py::str(c.name)] = py::cast(c.texts);
        formats[py::str(c.name)] = "%s";
        break;
    }
  }
  return py::make_tuple(columns, formats);
}

// The resolved scene (describe_scene's YAML) as nested dicts and lists of strings.
py::object yaml_to_python(const YAML::Node& node) {
  if (node.IsMap()) {
    py::dict d;
    for (const auto& kv : node) d[py::str(kv.first.as<std::string>())] = yaml_to_python(kv.second);
    return d;
  }
  if (node.IsSequence()) {
    py::list l;
    for (const auto& v : node) l.append(yaml_to_python(v));
    return l;
  }
  if (node.IsNull()) return py::none();
  return py::str(node.as<std::string>());
}

py::dict timings_dict(const twb::RunTimings& t) {
  py::dict d;
  d["total_ms"] = t.total_ms;
  d["setup_ms"] = t.setup_ms;
  d["solve_ms"] = t.solve_ms;
  d["states"] = t.states;
  d["newton_iterations"] = t.newton_iterations;
  d["jacobian_evaluations"] = t.jacobian_evaluations;
  d["transients"] = t.transients;
  d["ida_steps"] = t.ida_steps;
  d["ida_factorizations"] = t.ida_factorizations;
  d["klu_factorizations"] = t.klu_factorizations;
  return d;
}

py::list unknowns_list(const twb::Scene& scene) {
  std::vector<twb::UnknownBlock> blocks;
  {
    py::gil_scoped_release no_gil;  // building the model takes a while on fine meshes
    blocks = twb::Bearing(scene).unknowns();
  }
  py::list out;
  for (const twb::UnknownBlock& b : blocks) {
    py::dict d;
    d["name"] = b.name;
    d["effect"] = twb::effect_name(b.effect);
    d["size"] = b.size;
    out.append(d);
  }
  return out;
}

// The progress callback runs on whichever thread a search reports from: it takes the
// GIL for the call, and there Python's signals are looked at too (Ctrl-C), on the main
// thread, whether or not there is a callback. An exception from either cannot unwind
// through the solvers' threads: the first is kept, the study is told to stop (the
// searches under way finish, no new one begins), and it is raised once the study ends.
class ProgressRelay {
 public:
  explicit ProgressRelay(py::object callback) : callback_(std::move(callback)) {}
  twb::ProgressReport report() {
    return [this](const std::string& line) {
      if (stop_.load()) return;
      py::gil_scoped_acquire gil;
      try {
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        if (!callback_.is_none()) callback_(line);
      } catch (...) {
        const std::lock_guard lock(mutex_);
        if (!error_) error_ = std::current_exception();
        stop_.store(true);
      }
    };
  }
  const std::atomic<bool>* stop() const { return &stop_; }
  bool failed() const { return stop_.load(); }
  void raise_if_failed() {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  py::object callback_;
  std::mutex mutex_;
  std::exception_ptr error_;
  std::atomic<bool> stop_{false};
};

// continue_from: a duty cycle's end state to go on from, as its text (cycle_end_state.json's,
// of a Results), or for any other study the washer a life wore (worn_washer.json's), or
// the results directory that holds either; directory: the results directory
// to run into as `twb run` does (none: nothing written; claimed before the model is built;
// not written where the progress callback raised or Ctrl-C stopped the study, whose
// finished searches its journal keeps); resume: keep the searches a killed run journaled
// there (twb run --resume).
py::dict run_scene(const twb::Scene& given, py::object progress, int threads,
                   std::optional<std::string> continue_from_text, std::optional<std::string> continue_from,
                   std::optional<std::string> directory, bool resume) {
  twb::Scene scene = given;
  std::optional<twb::CycleState> cycle_start;
  // (The text of a Results: a duty cycle's end state where the Results have one, else a
  // worn washer; twb.run picks.)
  if (continue_from_text && continue_from_text->find("twb-cycle-state") != std::string::npos) {
    cycle_start = twb::cycle_state_of(*continue_from_text, "continue_from");
  } else if (continue_from_text) {
    twb::set_worn_washer(scene, twb::worn_washer_of(*continue_from_text, "the worn washer"), "continue_from");
  } else if (continue_from) {
    cycle_start = twb::continue_from(scene, *continue_from, directory.value_or(""), "continue_from");
  }
  if (resume && !directory) throw std::invalid_argument("resume=True needs out=DIR: the directory whose journal to resume");
  // Before the directory is claimed (and an earlier run's files in it removed).
  if (threads < 0)
    throw std::invalid_argument("threads must be 0 (one per core) or a positive count, not " + std::to_string(threads));
  ProgressRelay relay(std::move(progress));
  const twb::ProgressReport report = relay.report();
  const twb::RunOptions options{.threads = threads, .stop = relay.stop(),
                                .cycle_start = cycle_start ? &*cycle_start : nullptr};
  twb::StudyOutcome outcome;
  {
    py::gil_scoped_release no_gil;
    std::optional<twb::ResultsDirectory> results;
    if (directory) results.emplace(*directory);
    twb::Bearing bearing(scene);
    outcome = results ? bearing.run_into(*results, twb::ResultsRun{.resume = resume}, report, options)
                      : bearing.run_study(report, options);
  }
  relay.raise_if_failed();

  py::dict tables, formats;
  for (const twb::NamedTable& t : twb::study_tables(outcome, scene.study.type())) {
    py::tuple cf = table_columns(t.table);
    tables[py::str(t.name)] = cf[0];
    formats[py::str(t.name)] = cf[1];
  }
  py::list fields;
  for (const twb::SolvedState& s : outcome.states) {
    if (s.fields.empty()) {
      fields.append(py::none());
      continue;
    }
    fields.append(table_columns(twb::fields_table(s.fields))[0]);
  }
  py::dict out;
  out["tables"] = tables;
  out["formats"] = formats;
  out["fields"] = fields;
  out["summary"] = twb::summary_lines(outcome);
  out["limit_notes"] = twb::limit_notes(outcome.states, outcome.distress, outcome.parameter_columns,
                                           outcome.speeds_in_rpm);
  out["diagnostics"] = outcome.diagnostics;
  out["solver_failed"] = outcome.solver_failed;
  out["message"] = outcome.message;
  out["timings"] = timings_dict(outcome.timings);
  const twb::DutyCycleOutcome* cycle = outcome.duty_cycle();
  out["cycle_end"] = cycle && cycle->end ? py::object(py::str(twb::cycle_state_json(*cycle->end))) : py::none();
  const twb::LifeOutcome* life = outcome.life();
  out["worn_washer"] = life && !life->worn.empty() ? py::object(py::str(twb::worn_washer_json(life->worn.back())))
                                                   : py::none();
  return out;
}

}  // namespace

PYBIND11_MODULE(_twb, m) {
  m.doc() = "twb's compiled core; use the twb package (import twb).";
  m.attr("__version__") = twb::version();

  // twb.SceneError: the located message as str(e), and where: file, line, column.
  static py::exception<twb::InputError> scene_error(m, "SceneError", PyExc_ValueError);
  static py::exception<twb::SolverFailure> solver_failure(m, "SolverFailure", PyExc_RuntimeError);
  // twb.InternalError: a broken precondition inside twb (twb/error_family.h), with the
  // request to report it, as the command's exit status 4 says. An I/O error (exit status
  // 5) is Python's OSError.
  static py::exception<twb::InternalError> internal_error(m, "InternalError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const twb::InputError& e) {
      py::object error = py::handle(scene_error.ptr())(e.what());
      error.attr("file") = e.file();
      error.attr("line") = e.line();
      error.attr("column") = e.column();
      error.attr("message") = e.message();
      PyErr_SetObject(scene_error.ptr(), error.ptr());
    } catch (const twb::SolverFailure& e) {
      PyErr_SetString(solver_failure.ptr(), e.what());
    } catch (const twb::InternalError&) {
      PyErr_SetString(internal_error.ptr(), twb::report_error(std::current_exception()).message.c_str());
    } catch (const twb::IoError& e) {
      // Python's own error for a file that cannot be written: OSError(errno, message), which
      // Python makes the errno's subclass (NotADirectoryError, PermissionError, ...). No
      // filename: the message names the path already, and str() would name it twice.
      py::object error = e.error_number() != 0 ? py::handle(PyExc_OSError)(e.error_number(), e.what())
                                               : py::handle(PyExc_OSError)(e.what());
      PyErr_SetObject(PyExc_OSError, error.ptr());
    }
  });
  // Only for the test of the translation above: no input reaches an internal error.
  m.def("_raise_internal_error", [](const std::string& what) { throw twb::InternalError(what); });

  py::class_<twb::Scene>(m, "Scene")
      .def_readonly("source", &twb::Scene::source)
      .def_readonly("warnings", &twb::Scene::warnings)
      .def_property_readonly("study_type",
                             [](const twb::Scene& s) {
                               // Each level held by a name: an accessor into a temporary
                               // dangles once the statement ends.
                               const py::object scene = yaml_to_python(YAML::Load(twb::describe_scene(s)));
                               const py::object study = scene["study"];
                               return py::object(study["type"]);
                             })
      .def("resolved_yaml", [](const twb::Scene& s) { return twb::describe_scene(s); })
      .def("resolved_text", [](const twb::Scene& s) { return yaml_to_python(YAML::Load(twb::describe_scene(s))); })
      .def("record_json", [](const twb::Scene& s) { return twb::scene_record_json(s); })
      .def("unknowns", &unknowns_list)
      .def("inputs", [](const twb::Scene& s) {
        py::list out;
        for (const twb::SceneInput& in : s.inputs) out.append(py::make_tuple(in.path, in.value, in.unit));
        return out;
      });

  m.def("load_scene", &twb::load_scene, py::arg("path"), py::arg("overrides") = std::vector<std::string>{},
        py::call_guard<py::gil_scoped_release>());
  m.def("load_scene_text", &twb::load_scene_text, py::arg("text"), py::arg("name"),
        py::arg("overrides") = std::vector<std::string>{}, py::call_guard<py::gil_scoped_release>());
  m.def(
      "value_sources",
      [](const std::string& path, const std::vector<std::string>& overrides) {
        py::list out;
        for (const twb::ValueSource& v : twb::scene_value_sources(path, overrides))
          out.append(py::make_tuple(v.path, v.file, v.line));
        return out;
      },
      py::arg("path"), py::arg("overrides") = std::vector<std::string>{});
  m.def("run", &run_scene, py::arg("scene"), py::arg("progress") = py::none(), py::arg("threads") = 0,
        py::arg("continue_from_text") = py::none(), py::arg("continue_from") = py::none(), py::arg("out") = py::none(),
        py::arg("resume") = false);

  // One bearing for point after point (twb::Bearing): each state a mapping of states.csv's
  // columns to their values, unrounded.
  py::class_<twb::Bearing>(m, "Bearing")
      .def(py::init<const twb::Scene&>(), py::call_guard<py::gil_scoped_release>())
      .def("solve",
           [](twb::Bearing& b, double load, double speed) {
             twb::SolvedState s;
             {
               py::gil_scoped_release no_gil;
               s = b.solve(load, speed);
             }
             py::dict state;
             const twb::ResultTable table = twb::states_table({s});
             for (const twb::ResultColumn& c : table.columns()) {
               if (c.kind == twb::ResultColumn::Kind::text) state[py::str(c.name)] = c.texts.front();
               else if (c.kind == twb::ResultColumn::Kind::count) state[py::str(c.name)] = static_cast<long long>(c.numbers.front());
               else state[py::str(c.name)] = c.numbers.front();
             }
             return state;
           },
           py::arg("load"), py::arg("speed"))
      .def("sensitivity",
           [](twb::Bearing& b, const std::string& path) {
             std::vector<std::pair<std::string, double>> d;
             {
               py::gil_scoped_release no_gil;
               d = b.sensitivity(path);
             }
             py::dict out;
             for (const auto& [name, value] : d) out[py::str(name)] = value;
             return out;
           },
           py::arg("path"))
      .def("forget_state", &twb::Bearing::forget_state);
}
