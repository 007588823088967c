#include "pbrfit/jobs/brdf/brdf_inputs.hpp"

namespace pbrfit::jobs::brdf {

const std::vector<std::string>& brdf_parameter_names() {
  static const std::vector<std::string> names = {"p0", "p1", "p2", "p3"};
  return names;
}

}  // namespace pbrfit::jobs::brdf
