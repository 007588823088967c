#pragma once
// Parameter alignment after fitting (Kt et al. 2022; Nahmias 2022, section 3.4.1). M, c M R(phi) and
// c M R(phi) F, for c > 0, R(phi) a rotation about z and F = diag(1, -1, 1), are the same LTC, so two
// neighbouring table entries can be good fits and still interpolate to a wrong lobe. Both functions return
// the representative M F^k R(phi) (k = 0 or 1) closest to a reference:
//  - align_to_matrix: closest in the Frobenius norm once both matrices are scaled to unit Frobenius norm
//    (phi in closed form); the reference is typically a neighbour's fit;
//  - align_to_samples: smallest mean squared distance between normalize(M' s) and normalize(reference s)
//    over the given cosine samples s; with the identity as reference this is the thesis's "closest to the
//    cosine's own samples". phi: a scan of 72 angles per k, refined by golden-section search.
//
// Invariants: the result is the same LTC as M with M's scale (|det| and Frobenius norm unchanged);
// deterministic.
#include <span>

#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::ltc {

Matrix3 rotation_about_z(double phi);

Matrix3 align_to_matrix(const Matrix3& m, const Matrix3& reference);

Matrix3 align_to_samples(const Matrix3& m, const Matrix3& reference, std::span<const Vector3> base_samples);

}  // namespace pbrfit::ltc
