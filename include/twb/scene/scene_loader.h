// Scene files (YAML, docs/scenes.md) to the validated Scene of scene.h, and back.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "twb/scene/scene.h"

namespace twb {

// Reads, converts to SI and validates the scene file at `path`, then applies `overrides`:
// "dotted.path=value" texts from `twb run --set` (e.g. "operating.load=800 N",
// "effects=[hydrodynamics, asperity_contact]"), validated exactly like the file.
// Throws InputError (input_error.h) for any defect, naming the file, line and column, or
// the override.
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {});

// The same for the text of a scene file; `name` stands for the file in messages.
Scene load_scene_text(const std::string& text, const std::string& name,
                      const std::vector<std::string>& overrides = {});

// Where each value of a scene was written (docs/scenes.md, "Scenes that extend scenes"):
// its path, the file (or "--set path" for an override) and the line (0 for an override).
// Call after load_scene succeeded on the same arguments.
struct ValueSource {
  std::string path, file;
  int line = 0;
};
std::vector<ValueSource> scene_value_sources(const std::string& path, const std::vector<std::string>& overrides = {});

// The resolved scene as a scene file: every default filled in, values in SI written as
// "value unit" strings, so that loading the text back gives the same Scene.
std::string describe_scene(const Scene& scene);

// How the scene file spells a sliding film ("carrier_washer", "washer_gear"), for the
// results that name it.
std::string_view scene_name(SlidingFilm film);
// How the scene file spells a study type ("point", "duty_cycle"), for the messages that name it.
std::string_view scene_name(StudyType type);

}  // namespace twb
