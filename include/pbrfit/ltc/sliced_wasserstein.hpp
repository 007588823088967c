#pragma once
// The sliced Wasserstein distance between an LTC and a set of target directions (Bonneel et al. 2015, the
// loss of Kt et al. 2022 and of Nahmias 2022 for anisotropic LTC fits), with everything random held fixed:
//   SW(M) = (1 / P) sum_p (1 / n) sum_i | sort_i(a_p . normalize(M s_k)) - sort_i(a_p . t_k) |
// over P projection axes a_p and n base cosine samples s_k, one per target t_k. By default the axes are
// axis_directions(P) and the samples are the cosine samples of golden_lattice(n) (point_sets.hpp), so SW is a
// deterministic, continuous, piecewise-smooth function of M, unchanged by M -> c M for c > 0.
//
// gradient() is d SW / d M with the sorted pairing held fixed and d|x| / dx = sign(x) (0 at 0); it drives the
// SGD baseline.
//
// Invariants: the targets' sorted projections are computed once, by the constructor; distance() and
// gradient() allocate nothing (the object owns its scratch space, so it is not shared between threads);
// targets and base samples are unit vectors, base samples have z > 0, and there is one base sample per target
// (fewer than 2^32).
// Samples are ordered on each axis by (projection, index), a total order (NaN after +inf), so the pairing of
// samples with targets is a function of M alone, even where projections tie. Each axis keeps the order of the
// previous call and re-ranks from it, counting each sample's rank among its neighbours in that order (an
// optimizer's successive matrices are close, so samples move a few places); where one moved too far, or two
// projections tie, the axis is ranked among all samples instead (both vector kernels, projection_sort.hpp).
// Either way gives the same order: the values returned do not depend on that history or on the kernel set.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "pbrfit/geometry/vector.hpp"

namespace pbrfit::ltc {

class SlicedWasserstein {
 public:
  explicit SlicedWasserstein(std::span<const Vector3> targets, std::size_t axis_count = 32);
  SlicedWasserstein(std::span<const Vector3> targets, std::vector<Vector3> base, std::vector<Vector3> axes);

  double distance(const Matrix3& m);
  // SW(M), with d SW / d M written to `gradient`.
  double gradient(const Matrix3& m, Matrix3& gradient);

  std::span<const Vector3> base() const { return base_; }

 private:
  void transform_base(const Matrix3& m);
  Vector3 transformed(std::size_t k) const;  // normalize(M s_k) of the last transform_base
  // Projects the transformed samples on axis p and sorts them: afterwards order(p) lists sample indices by
  // (projection, index), projections_ the projections in that order.
  void sort_projections(std::size_t p);
  // Ranks values (any NaN ranks after +inf) into sorted and order by the vector kernel.
  void rank_sort(const double* values, double* sorted, std::uint32_t* order);
  std::uint32_t* order(std::size_t p) { return orders_.data() + p * base_.size(); }

  std::vector<Vector3> base_;
  std::vector<Vector3> axes_;
  std::vector<double> sorted_targets_;  // [axis][rank]
  std::vector<double> transformed_;     // normalize(M s_k) as three arrays: all x, all y, all z
  std::vector<double> lengths_;         // |M s_k|
  std::vector<double> values_;          // projections on the current axis, by sample
  std::vector<double> keys_;            // values_ with NaN as +inf, when there is a NaN
  std::vector<double> rerank_keys_;     // the re-rank's scratch: projections in the last order, padded
  std::vector<std::uint32_t> rerank_order_;  // ... and the new order until it is checked
  std::vector<double> projections_;     // sorted projections on the current axis
  std::vector<double> signed_sums_;     // gradient(): per sample, sums over axes of sign * axis (all x, y, z) and
                                        // of sign * projection
  std::vector<double> signs_;           // gradient(): the current axis' signs, by sample
  std::vector<std::uint32_t> orders_;   // [axis][rank]: sample indices by projection, from the last call
  std::vector<bool> ordered_;           // per axis: whether orders_ comes from a previous call
};

}  // namespace pbrfit::ltc
