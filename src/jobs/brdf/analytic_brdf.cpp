#include "pbrfit/jobs/brdf/analytic_brdf.hpp"

#include <memory>
#include <stdexcept>

#include "pbrfit/gp/expression_parser.hpp"
#include "pbrfit/gp/tree_walker.hpp"
#include "pbrfit/jobs/brdf/brdf_inputs.hpp"

namespace pbrfit::jobs::brdf {

render::BrdfFunction analytic_brdf(const gp::CompiledTree& tree, const std::vector<std::vector<double>>& parameters) {
  if (parameters.size() != 3) throw std::invalid_argument("analytic_brdf: parameters for three channels");
  auto programs = std::make_shared<std::array<gp::Program, 3>>();
  for (std::size_t c = 0; c < 3; ++c) {
    (*programs)[c] = tree.program;
    gp::set_parameters((*programs)[c], tree.parameter_slots, parameters[c]);
  }
  return [programs](const Vector3& wi, const Vector3& wo) -> render::Rgb {
    if (wi.z() <= 0.0 || wo.z() <= 0.0) return {0.0, 0.0, 0.0};
    const auto row = pbrfit::brdf::direction_inputs(wi, wo);
    render::Rgb value;
    for (std::size_t c = 0; c < 3; ++c) value[c] = gp::walk_tree<double>((*programs)[c], std::span<const double>(row));
    return value;
  };
}

}  // namespace pbrfit::jobs::brdf
