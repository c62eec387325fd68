// A run that goes on from where an earlier one ended: a duty cycle's end state, or the
// washer a life wore (docs/scenes.md, "Going on from an earlier run").
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "twb/scene/scene_loader.h"
#include "twb/study/study_outcome.h"

namespace twb {

void set_worn_washer(Scene& scene, WornWasher worn, std::string_view asked_by) {
  auto refuse = [&](const std::string& why) {
    return std::invalid_argument(fmt::format("{} {}: {}", asked_by, worn.source, why));
  };
  if (!scene.effects.wear)
    throw refuse("a worn washer's depths are the wear effect's: add wear to the scene's effects (and each face's "
                 "surfaces.<body>.wear_rate), as configs/effects/wear.yaml does");
  const int film = scene.operating.sliding == SlidingFilm::carrier_washer ? 1 : 2;
  if (worn.film != film)
    throw refuse(fmt::format("the washer was worn where film {} slides; this scene's sliding film is film {} "
                             "(operating.sliding: {})",
                             worn.film, film, scene_name(scene.operating.sliding)));
  const auto [inner, outer] = film_radii(scene, film);
  auto same = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::abs(b); };
  if (!same(worn.inner_radius, inner) || !same(worn.outer_radius, outer))
    throw refuse(fmt::format("its sliding film spans {:.6g}-{:.6g} mm, this scene's {:.6g}-{:.6g} mm: the depths "
                             "belong to another washer",
                             1e3 * worn.inner_radius, 1e3 * worn.outer_radius, 1e3 * inner, 1e3 * outer));
  if (const LifeSettings* life = std::get_if<LifeSettings>(&scene.study.settings);
      life && !(life->duration > worn.time * (1.0 + 1e-12)))
    throw refuse(fmt::format("the washer has lived {:.6g} h, and study.duration ({:.6g} h) is the whole life's from "
                             "new: a continued life needs a longer one",
                             worn.time / 3600.0, life->duration / 3600.0));
  scene.worn = std::make_shared<const WornWasher>(std::move(worn));
}

std::optional<CycleState> continue_from(Scene& scene, const std::string& from, const std::string& out,
                                        std::string_view asked_by) {
  const std::filesystem::path file = std::filesystem::path(from) / "worn_washer.json";
  // A duty cycle goes on from an earlier cycle's end, or runs the washer a life wore.
  if (scene.study.type() == StudyType::duty_cycle && !std::filesystem::exists(file))
    return cycle_to_continue(scene.study, from, out, asked_by);
  std::error_code same_error;
  if (!out.empty() && std::filesystem::equivalent(out, from, same_error))
    throw std::invalid_argument(fmt::format("{} {}: the run's results go to another directory, or they would "
                                            "replace the washer it starts from",
                                            asked_by, from));
  if (!std::filesystem::exists(file))
    throw std::invalid_argument(fmt::format("{} {}: no worn_washer.json there; a {} study goes on from the washer a "
                                            "life study wore (its results directory), a duty cycle from where an "
                                            "earlier cycle ended",
                                            asked_by, from, scene_name(scene.study.type())));
  set_worn_washer(scene, read_worn_washer(file.string()), asked_by);
  return std::nullopt;
}

}  // namespace twb
