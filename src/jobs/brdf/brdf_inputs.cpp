#include "pbrfit/jobs/brdf/brdf_inputs.hpp"

namespace pbrfit::jobs::brdf {

const std::vector<std::string>& brdf_input_names() {
  static const std::vector<std::string> names = {"nl", "nv", "nh", "vh", "lv", "rv", "hr", "lr"};
  return names;
}

const std::vector<std::string>& brdf_parameter_names() {
  static const std::vector<std::string> names = {"p0", "p1", "p2", "p3"};
  return names;
}

std::array<double, brdf_input_count> brdf_inputs(const ltc::Vector3& l, const ltc::Vector3& v) {
  const ltc::Vector3 n = ltc::Vector3::UnitZ();
  const ltc::Vector3 h = (l + v).normalized();
  const ltc::Vector3 r = 2.0 * l.z() * n - l;
  return {l.z(), v.z(), h.z(), v.dot(h), l.dot(v), r.dot(v), h.dot(r), l.dot(r)};
}

}  // namespace pbrfit::jobs::brdf
