#pragma once
// A linearly transformed cosine (Heitz, Dupuy, Hill & Neubelt 2016): the clamped cosine D_o transformed by
// an invertible 3x3 matrix M, times an amplitude. For a unit direction w,
//   D(w) = amplitude * D_o(M^-1 w / |M^-1 w|) * |det M^-1| / |M^-1 w|^3.
//
// Invariants:
//  - D integrates to `amplitude` over the sphere for every invertible M (the Jacobian term makes the
//    transformed density a density);
//  - D is unchanged by M -> c M R F for c > 0, R a rotation about z and F = diag(1, -1, 1) (D_o is);
//  - sample(u1, u2) = normalize(M s) for the cosine sample s of (u1, u2), whose density is pdf() = D /
//    amplitude; transform() gives the same direction together with D at it without evaluating M^-1;
//  - the constructor throws std::invalid_argument for a singular or non-finite M, or an amplitude < 0.
#include <span>

#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::ltc {

class LtcDistribution {
 public:
  explicit LtcDistribution(const Matrix3& m, double amplitude = 1.0);

  const Matrix3& matrix() const { return m_; }
  const Matrix3& inverse() const { return m_inverse_; }
  double amplitude() const { return amplitude_; }

  // D(w) / amplitude for a unit direction w.
  double pdf(const Vector3& w) const;
  // D(w) for a unit direction w.
  double evaluate(const Vector3& w) const { return amplitude_ * pdf(w); }
  Vector3 sample(double u1, double u2) const;

  struct Transformed {
    Vector3 direction;  // normalize(M base)
    double pdf = 0.0;   // D / amplitude at direction
  };
  // For a unit base direction with base.z > 0 (a cosine sample).
  Transformed transform(const Vector3& base) const;
  // transform() and pdf() over many directions (spans of equal length), bit for bit the same, as vector
  // code of the process's kernel set.
  void transform_many(std::span<const Vector3> base, std::span<Vector3> direction, std::span<double> pdf) const;
  void pdf_many(std::span<const Vector3> w, std::span<double> pdf) const;

  // The integral of D over the solid angle a planar polygon subtends (polygon_integral.hpp): the
  // amplitude times the clamped-cosine integral over M^-1 P.
  double integrate_polygon(std::span<const Vector3> vertices) const;

 private:
  Matrix3 m_;
  Matrix3 m_inverse_;
  double inverse_determinant_;  // |det M^-1|
  double amplitude_;
};

}  // namespace pbrfit::ltc
