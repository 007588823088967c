#pragma once
// A lobe (lobe.hpp) known only through its values, such as a BRDF written as an expression or a measured
// material: rho(l) is given as a function, and directions are drawn from a piecewise-constant table of it
// mixed with cosine sampling, so that any lobe is covered without knowing its shape.
//
// The table lives in polar coordinates about the lobe's peak axis (the largest of rho over the mirror
// direction, the view, the normal and an equal-area probe grid of the hemisphere): polar_bins rings with
// edges at pi (i / polar_bins)^2 (narrow near the peak, so sharp specular lobes are resolved) times
// azimuth_bins sectors, over the whole sphere. A cell's weight is its solid angle times the mean of rho at its
// four corners and its centre (the centre counted four times); within a cell directions are uniform in solid
// angle. The density is
//   pdf(l) = cosine_share max(n.l, 0) / pi + (1 - cosine_share) weight(cell of l) / (total weight x solid angle),
// pure cosine sampling when every probe of rho is 0.
//
// Invariants: as Lobe; rho is evaluated only by the constructor (about 4,000 times for the defaults) and by
// evaluate(); the table is a deterministic function of (view, rho, options); rho must be >= 0, finite and 0
// below the horizon (negative or non-finite probes throw std::invalid_argument).
#include <cstddef>
#include <functional>
#include <vector>

#include "pbrfit/brdf/lobe.hpp"

namespace pbrfit::brdf {

struct TabulationOptions {
  std::size_t polar_bins = 64;
  std::size_t azimuth_bins = 32;
  double cosine_share = 0.2;  // in (0, 1]
};

class TabulatedLobe final : public Lobe {
 public:
  using Function = std::function<double(const Vector3& l)>;

  TabulatedLobe(double cos_theta_view, Function rho, const TabulationOptions& options = {});

  Evaluation evaluate(const Vector3& l) const override;
  Vector3 sample(double u1, double u2) const override;
  double value(const Vector3& l) const override { return rho_(l); }
  std::optional<Vector3> peak() const override { return frame_.z; }  // the table's axis

 private:
  std::size_t cell_of(const Vector3& local) const;
  double pdf(const Vector3& l) const;

  Function rho_;
  TabulationOptions options_;
  Frame frame_;
  std::vector<double> ring_cosines_;  // cos of the ring edges, polar_bins + 1, decreasing from 1 to -1
  std::vector<double> cumulative_;    // of the cells' probabilities, ring-major
  std::vector<double> density_;       // per cell: probability / solid angle
  std::size_t last_cell_ = 0;         // the last cell of probability > 0
  double cosine_share_ = 1.0;
};

}  // namespace pbrfit::brdf
