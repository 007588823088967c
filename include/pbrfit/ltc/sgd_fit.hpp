#pragma once
// The baseline anisotropic fit of Nahmias 2022 (section 3.4.1, after Kt et al. 2022): plain stochastic
// gradient descent on the sliced Wasserstein loss from M = identity. Each epoch draws fresh cosine base
// samples (one per target) and fresh projection axes (uniform on the sphere) from the random stream, then
// steps M -= learning_rate * loss_scale * d SW / d M; loss_scale is multiplied by loss_scale_decay after
// every epoch. The defaults are the thesis's: 100 epochs, 32 axes, learning rate 1, scale 0.1, decay 0.999.
//
// Invariants: the same stream state gives bitwise the same matrix; no alignment, no normalization.
#include <cstddef>
#include <span>

#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::ltc {

struct SgdOptions {
  int epochs = 100;
  std::size_t axes = 32;
  double learning_rate = 1.0;
  double loss_scale = 0.1;
  double loss_scale_decay = 0.999;
};

Matrix3 sgd_fit_from_identity(std::span<const Vector3> targets, const SgdOptions& options, RandomStream& random);

}  // namespace pbrfit::ltc
