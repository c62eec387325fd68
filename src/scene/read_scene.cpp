// The scene file's top level: which sections exist, in the order the physics needs them
// (the operating limits depend on the lubricant's viscosity law, the asperity defaults
// on the surfaces).
#include "scene_sections.h"

namespace twb::scene_io {

Scene read_scene(const Node& root) {
  const MapReader scene(root, {"effects", "geometry", "materials", "surfaces", "lubricant",
                               "limits", "operating", "friction", "mesh", "solver", "study", "output"});
  Scene out;
  out.effects = read_effects(scene);
  read_bodies(scene, out);
  read_operation(scene, out);
  read_numerics(scene, out);
  read_grooves(scene, out);
  check_groove_parameter(scene, out);
  return out;
}

}  // namespace twb::scene_io
