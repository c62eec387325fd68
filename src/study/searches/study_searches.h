// A study's distress searches: one per configuration of the bearing (the scene's own, a
// value of its second parameter, or a sliding film) and speed, on threads, journaled, or
// spread over slices and MPI ranks (search_scheduler.h), each with its error bars.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "model/bearing_model.h"
#include "study/searches/distress_search.h"
#include "study/parallel/parallel.h"
#include "twb/results/run_timings.h"

namespace twb {

class SearchJournal;
class SearchScheduler;

// The name of a parameter's column in the results, with its unit.
std::string parameter_column(MapParameter p);
// An axis' column: a named parameter's, or an input's path with its SI unit, e.g.
// "geometry.gear.tilt_rad", "materials.washer.conductivity_W_m_K".
std::string parameter_column(const MapAxis& axis);
std::string input_column(const std::string& path, const std::string& unit);
// Applies a value of one of a study's axes to a scene.
Scene with_parameter(Scene scene, const MapAxis& axis, double value);

// One configuration of the bearing a study searches at every speed: the scene's own
// (no scene here), a combination of its axes' values, or a sliding film.
struct Variant {
  std::optional<Scene> scene;
  std::vector<double> parameters;  // one per axis (run_axes.h)
  std::optional<SlidingFilm> sliding;
  std::string label;  // for progress lines, e.g. ", friction_coefficient = 0.1"
};

// The scene's own configuration, or one per combination of its axes' values (the first
// axis outermost); `columns` gets the axes' columns.
std::vector<Variant> parameter_variants(const Scene& scene, std::vector<std::string>& columns);

// The speeds a study searches at: its settings' speeds, or the model's speed for a type
// without them or a scene built without them (the loader fills them in).
std::vector<double> study_speeds(const BearingModel& model);

// Called after each search with the speed's index in study_speeds and a model of its
// variant, whose films (not its speed) a taker may read.
using SearchResult = std::function<void(const Variant&, std::size_t speed, const BearingModel&, DistressSearch&)>;

// How a study's searches run: on how many threads here, journaled where, spread how.
struct Running {
  int threads = 1;
  const SearchJournal* journal = nullptr;
  SearchScheduler* scheduler = nullptr;
  const std::atomic<bool>* stop = nullptr;
};

// One distress search per variant and speed, on `threads` threads. Every search builds
// its own model and solvers, so a search's numbers do not depend on which thread ran it
// or on what ran before; results are handed to `take` in the order of the study (variant
// outer, speed inner), each as soon as all before it are, so the study's files are the
// same, byte for byte, whatever the thread count. Progress lines "[k/n] ..." with the time
// left; a search that throws becomes a failed row, so that the study's other searches are
// kept.
void run_searches(BearingModel& base, const std::vector<Variant>& variants, const DistressSearchSettings& settings,
                  const ProgressReport& progress, const Running& how, RunTimings& timings,
                  std::vector<std::string>& diagnostics, const SearchResult& take);

}  // namespace twb
