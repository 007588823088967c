#pragma once
// A compiled BRDF expression (gp/syntax_tree.hpp) of the inputs of brdf_inputs.hpp (brdf/direction_inputs.hpp) with fitted parameters
// per colour channel, as a renderable BRDF (render/brdf_function.hpp).
//
// Invariants: channel c evaluates the program with parameters[c] in its parameter slots (double precision,
// the tree walker); below the horizon (n.l or n.v <= 0) the value is 0; a value that is not finite stays
// as it is (renders show it as black), so a broken fit is visible rather than hidden.
#include <array>
#include <vector>

#include "pbrfit/gp/syntax_tree.hpp"
#include "pbrfit/render/brdf_function.hpp"

namespace pbrfit::jobs::brdf {

render::BrdfFunction analytic_brdf(const gp::CompiledTree& tree, const std::vector<std::vector<double>>& parameters);

}  // namespace pbrfit::jobs::brdf
