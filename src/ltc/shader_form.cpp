#include "pbrfit/ltc/shader_form.hpp"

#include <cmath>
#include <stdexcept>

namespace pbrfit::ltc {

ShaderForm shader_form(const Matrix3& m) {
  const double determinant = m.determinant();
  if (!std::isfinite(determinant) || determinant == 0.0) throw std::invalid_argument("ltc: singular matrix");
  const Matrix3 inverse = m.inverse();
  const double middle = inverse(1, 1);
  if (middle == 0.0 || !std::isfinite(middle)) throw std::invalid_argument("ltc: the inverse's middle entry is 0");
  return {inverse(0, 0) / middle, inverse(2, 0) / middle, inverse(0, 2) / middle, inverse(2, 2) / middle};
}

Matrix3 inverse_from_shader_form(const ShaderForm& form) {
  Matrix3 inverse;
  inverse << form[0], 0.0, form[2],  //
      0.0, 1.0, 0.0,                 //
      form[1], 0.0, form[3];
  return inverse;
}

Matrix3 matrix_from_shader_form(const ShaderForm& form) { return inverse_from_shader_form(form).inverse(); }

}  // namespace pbrfit::ltc
