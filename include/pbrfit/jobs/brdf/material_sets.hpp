#pragma once
// The material classes of genBRDF (Brady et al., Figures 5, 6 and 9): 20 metals and 20 dielectrics of the
// MERL database, each split into the 4 training and 16 testing materials of the paper's tables, by MERL
// name. The paper's "ornament" materials (Christmas ornaments) and phenolics have no MERL name of their own;
// they map to the closest MERL materials: Red, Gold, Green and Blue Ornament -> red-metallic-paint,
// gold-metallic-paint2, green-metallic-paint2, blue-metallic-paint2 (metallic-painted spheres); Green, Blue,
// Violet and Orange Phenolic -> specular-green-phenolic, specular-blue-phenolic, specular-violet-phenolic,
// specular-orange-phenolic.
#include <optional>
#include <string>
#include <vector>

namespace pbrfit::jobs::brdf {

struct MaterialSet {
  std::string name;  // "metals" or "dielectrics"
  std::vector<std::string> training;
  std::vector<std::string> testing;
};

const std::vector<MaterialSet>& material_sets();
std::optional<MaterialSet> material_set(const std::string& name);
// The 100 MERL material names, in the database's order.
const std::vector<std::string>& merl_material_names();

}  // namespace pbrfit::jobs::brdf
