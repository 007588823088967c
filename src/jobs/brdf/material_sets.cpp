#include "pbrfit/jobs/brdf/material_sets.hpp"

namespace pbrfit::jobs::brdf {

const std::vector<MaterialSet>& material_sets() {
  static const std::vector<MaterialSet> sets = {
      {"metals",
       {"steel", "two-layer-gold", "green-metallic-paint", "red-metallic-paint"},
       {"tungsten-carbide", "blue-metallic-paint", "gold-metallic-paint", "silver-metallic-paint", "silver-paint",
        "aluminium", "nickel", "chrome", "gold-paint", "gold-metallic-paint2", "black-oxidized-steel", "hematite",
        "green-metallic-paint2", "blue-metallic-paint2", "brass", "alum-bronze"}},
      {"dielectrics",
       {"maroon-plastic", "pvc", "green-acrylic", "dark-blue-paint"},
       {"specular-green-phenolic", "specular-blue-phenolic", "specular-violet-phenolic", "green-plastic",
        "gray-plastic", "specular-orange-phenolic", "dark-red-paint", "pure-rubber", "orange-paint",
        "black-soft-plastic", "neoprene-rubber", "blue-rubber", "violet-acrylic", "yellow-matte-plastic",
        "white-acrylic", "red-specular-plastic"}},
  };
  return sets;
}

std::optional<MaterialSet> material_set(const std::string& name) {
  for (const auto& set : material_sets())
    if (set.name == name) return set;
  return std::nullopt;
}

const std::vector<std::string>& merl_material_names() {
  static const std::vector<std::string> names = {
      "alum-bronze", "alumina-oxide", "aluminium", "aventurnine", "beige-fabric", "black-fabric", "black-obsidian",
      "black-oxidized-steel", "black-phenolic", "black-soft-plastic", "blue-acrylic", "blue-fabric",
      "blue-metallic-paint", "blue-metallic-paint2", "blue-rubber", "brass", "cherry-235", "chrome", "chrome-steel",
      "colonial-maple-223", "color-changing-paint1", "color-changing-paint2", "color-changing-paint3",
      "dark-blue-paint", "dark-red-paint", "dark-specular-fabric", "delrin", "fruitwood-241", "gold-metallic-paint",
      "gold-metallic-paint2", "gold-metallic-paint3", "gold-paint", "gray-plastic", "grease-covered-steel",
      "green-acrylic", "green-fabric", "green-latex", "green-metallic-paint", "green-metallic-paint2",
      "green-plastic", "hematite", "ipswich-pine-221", "light-brown-fabric", "light-red-paint", "maroon-plastic",
      "natural-209", "neoprene-rubber", "nickel", "nylon", "orange-paint", "pearl-paint", "pickled-oak-260",
      "pink-fabric", "pink-fabric2", "pink-felt", "pink-jasper", "pink-plastic", "polyethylene",
      "polyurethane-foam", "pure-rubber", "purple-paint", "pvc", "red-fabric", "red-fabric2", "red-metallic-paint",
      "red-phenolic", "red-plastic", "red-specular-plastic", "silicon-nitrade", "silver-metallic-paint",
      "silver-metallic-paint2", "silver-paint", "special-walnut-224", "specular-black-phenolic",
      "specular-blue-phenolic", "specular-green-phenolic", "specular-maroon-phenolic", "specular-orange-phenolic",
      "specular-red-phenolic", "specular-violet-phenolic", "specular-white-phenolic", "specular-yellow-phenolic",
      "ss440", "steel", "teflon", "tungsten-carbide", "two-layer-gold", "two-layer-silver", "violet-acrylic",
      "violet-rubber", "white-acrylic", "white-diffuse-bball", "white-fabric", "white-fabric2", "white-marble",
      "white-paint", "yellow-matte-plastic", "yellow-paint", "yellow-phenolic", "yellow-plastic"};
  return names;
}

}  // namespace pbrfit::jobs::brdf
