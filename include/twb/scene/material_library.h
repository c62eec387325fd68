// The materials twb ships (docs/materials.md): each with the sources of its values, taken
// in a scene by name (`materials.washer: peek`) and overridable field by field
// (`materials.washer: {material: peek, yield_strength: 80 MPa}`).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "twb/scene/scene.h"

namespace twb {

// A body's bulk material, or a coating: a face's layer, never a body of its own.
enum class MaterialForm { bulk, coating };

struct LibraryMaterial {
  std::string_view name;         // the scene's spelling
  std::string_view description;  // grade, condition, filler
  MaterialForm form;
  // youngs_modulus at room temperature (23 degC), with the data sheet's modulus over
  // temperature where it gives one (a polymer's falls by an order of magnitude through its
  // glass transition).
  Material properties;
  std::optional<double> glass_transition;  // K, polymers
  // A coating's usual thickness range (m), for the docs and for the check of a layer.
  std::optional<std::pair<double, double>> coating_thickness;
  std::string_view sources;  // where each value comes from, field by field
};

// Every shipped material, bulk ones first, in the order docs/materials.md lists them.
std::span<const LibraryMaterial> material_library();
// The material named `name`, or nullptr.
const LibraryMaterial* find_library_material(std::string_view name);
// The names of the library's materials of one form, in its order.
std::vector<std::string_view> library_material_names(MaterialForm form);

// The library as a Markdown table and its sources (docs/materials.md, `twb materials`).
std::string material_library_markdown();

}  // namespace twb
