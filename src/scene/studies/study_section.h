// A study type as the scene file sees it: its keys under `study`, how they are read and
// checked, and how the resolved study is written back (describe_scene, run.json). Each
// type is one file here, <type>_keys.cpp, registered in study_sections.cpp; what the type
// runs and writes is the study layer's (study/study_kind.h).
#pragma once

#include <span>
#include <string_view>

#include "scene/scene_node.h"
#include "scene/scene_text.h"
#include "twb/scene/scene.h"

namespace twb::scene_io {

struct StudySection {
  // Its keys under `study`, `type` among them: any other is refused "with type: ...".
  std::span<const std::string_view> keys;
  // Reads and checks its keys; the effects, bodies and operating point are read.
  void (*read)(const MapReader& study, Scene& out) = nullptr;
  // Reads what needs every input of the scene known (a reliability study's distributions,
  // a calibration's fitted inputs, a duty cycle's schedule); none for most types.
  void (*read_after_inputs)(const MapReader& scene, Scene& out) = nullptr;
  // Writes its keys after `type`, in a fixed order: run.json keeps the text, and a run
  // resumed from its journal compares it (tests/scene/study_section_test.cpp).
  void (*write)(SceneText& w, const Study& study) = nullptr;
};

const StudySection& study_section(StudyType type);

}  // namespace twb::scene_io
