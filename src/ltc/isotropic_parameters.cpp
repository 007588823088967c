#include "pbrfit/ltc/isotropic_parameters.hpp"

namespace pbrfit::ltc {

Matrix3 lobe_frame(const Vector3& average_direction) {
  const Vector3& z = average_direction;
  Matrix3 frame;
  frame << z.z(), 0.0, z.x(),  //
      0.0, 1.0, 0.0,           //
      -z.x(), 0.0, z.z();
  return frame;
}

Matrix3 isotropic_ltc_matrix(const IsotropicParameters& parameters, const Vector3& average_direction) {
  Matrix3 local;
  local << parameters.m00, 0.0, parameters.m02,  //
      0.0, parameters.m11, 0.0,                  //
      parameters.m20, 0.0, 1.0;
  return lobe_frame(average_direction) * local;
}

}  // namespace pbrfit::ltc
