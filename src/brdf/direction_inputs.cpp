#include "pbrfit/brdf/direction_inputs.hpp"

namespace pbrfit::brdf {

const std::vector<std::string>& direction_input_names() {
  static const std::vector<std::string> names = {"nl", "nv", "nh", "vh", "lv", "rv", "hr", "lr"};
  return names;
}

std::array<double, direction_input_count> direction_inputs(const Vector3& l, const Vector3& v) {
  const Vector3 n = Vector3::UnitZ();
  const Vector3 h = (l + v).normalized();
  const Vector3 r = 2.0 * l.z() * n - l;
  return {l.z(), v.z(), h.z(), v.dot(h), l.dot(v), r.dot(v), h.dot(r), l.dot(r)};
}

}  // namespace pbrfit::brdf
