#pragma once
// The tensor-product Gauss-Kronrod 7-15 rule over one box, with its error and split indicators.
//
// Invariants:
//  - the integrand is sampled once per point of the 15^Dim Kronrod grid; every Gauss or mixed tensor
//    rule reuses those samples (the G7 nodes are nested in K15);
//  - samples are taken in row-major order of the grid (x[0] slowest), so the evaluation order, and
//    therefore every floating-point result, depends only on the box; an integrand with the line fast path
//    (outer_binding.hpp) gives each line of 15 samples along the last axis in one call.
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "pbrfit/integrate/box.hpp"
#include "pbrfit/integrate/gauss_kronrod.hpp"
#include "pbrfit/integrate/outer_binding.hpp"

namespace pbrfit::integrate {

template <int Comp>
struct TileEstimate {
  std::array<double, Comp> value{};  // the K x ... x K estimate
  double error = 0.0;                // max over components of |K x ... x K - G x ... x G|
  int split_dimension = 0;           // argmax over d of max_c |K...K - K..G(in d)..K|, lowest d on ties
};

template <int Dim, int Comp>
class TensorGaussKronrod {
 public:
  static_assert(Dim >= 1 && Comp >= 1);
  static constexpr int rule_patterns = 1 << Dim;  // bit d set: Gauss along axis d, else Kronrod

  static constexpr std::size_t points_per_tile() {
    std::size_t points = 1;
    for (int d = 0; d < Dim; ++d) points *= gauss_kronrod::kronrod_size;
    return points;
  }

  TensorGaussKronrod() : samples_(points_per_tile() * Comp), scratch_(points_per_tile() * Comp) {}

  template <class Integrand>
  TileEstimate<Comp> estimate(const Integrand& f, const Box<Dim>& box) {
    sample_grid(f, box);
    contract_all_axes();
    return summarize(box);
  }

 private:
  using Coordinates = std::array<std::array<double, gauss_kronrod::kronrod_size>, Dim>;
  static constexpr int n = gauss_kronrod::kronrod_size;

  static Coordinates grid_coordinates(const Box<Dim>& box) {
    Coordinates coords{};
    for (int d = 0; d < Dim; ++d) {
      const double centre = 0.5 * (box.lo[d] + box.hi[d]);
      const double half_width = 0.5 * (box.hi[d] - box.lo[d]);
      for (int i = 0; i < n; ++i) coords[d][i] = centre + half_width * gauss_kronrod::kronrod_nodes[i];
    }
    return coords;
  }

  // Samples the slice of the grid with axes < first_axis fixed (already set in x), row-major,
  // writing Comp values per point to out.
  template <class Callable>
  static void sample_slice(const Callable& g, const Coordinates& coords, int first_axis,
                           std::array<double, Dim> x, double* out) {
    std::array<int, Dim> index{};
    for (int d = first_axis; d < Dim; ++d) x[d] = coords[d][0];
    while (true) {
      if constexpr (LineEvaluable<Callable, Dim>) {  // last axis, fastest
        g.line(x, coords[Dim - 1].data(), out);
        out += n * Comp;
      } else {
        for (int i = 0; i < n; ++i) {
          x[Dim - 1] = coords[Dim - 1][i];
          const std::array<double, Comp> value = g(x);
          for (int c = 0; c < Comp; ++c) out[c] = value[c];
          out += Comp;
        }
      }
      int d = Dim - 2;  // odometer over axes first_axis .. Dim-2
      while (d >= first_axis && ++index[d] == n) {
        index[d] = 0;
        x[d] = coords[d][0];
        --d;
      }
      if (d < first_axis) return;
      x[d] = coords[d][index[d]];
    }
  }

  template <class Integrand>
  void sample_grid(const Integrand& f, const Box<Dim>& box) {
    const Coordinates coords = grid_coordinates(box);
    if constexpr (Dim >= 2 && OuterBindable<Integrand, Dim, Comp>) {
      const std::size_t slice_values = points_per_tile() / n * Comp;
      for (int i0 = 0; i0 < n; ++i0) {
        std::array<double, Dim> x{};
        x[0] = coords[0][i0];
        const auto bound = f.bind_outer(x[0]);
        sample_slice(bound, coords, 1, x, samples_.data() + i0 * slice_values);
      }
    } else {
      sample_slice(f, coords, 0, std::array<double, Dim>{}, samples_.data());
    }
  }

  // Contracts the innermost remaining axis of every pattern block with both rules.
  // in: [pattern (patterns)][rows][n][Comp] -> out: [pattern * 2 + rule][rows][Comp], rule 1 = Gauss.
  static void contract_innermost(const double* in, double* out, std::size_t patterns, std::size_t rows) {
    for (std::size_t p = 0; p < patterns; ++p) {
      double* kronrod_out = out + (2 * p) * rows * Comp;
      double* gauss_out = out + (2 * p + 1) * rows * Comp;
      for (std::size_t r = 0; r < rows; ++r) {
        const double* line = in + (p * rows + r) * n * Comp;
        for (int c = 0; c < Comp; ++c) {
          double kronrod = 0.0;
          for (int i = 0; i < n; ++i) kronrod += gauss_kronrod::kronrod_weights[i] * line[i * Comp + c];
          double gauss = 0.0;
          for (int g = 0; g < gauss_kronrod::gauss_size; ++g) {
            gauss += gauss_kronrod::gauss_weights[g] * line[gauss_kronrod::gauss_node_position(g) * Comp + c];
          }
          kronrod_out[r * Comp + c] = kronrod;
          gauss_out[r * Comp + c] = gauss;
        }
      }
    }
  }

  // Leaves the 2^Dim tensor-rule sums (unscaled) in result_, indexed by pattern; axis Dim-1 is
  // contracted first, so after all axes bit d of the pattern index refers to axis d.
  void contract_all_axes() {
    double* in = samples_.data();
    double* out = scratch_.data();
    std::size_t patterns = 1;
    std::size_t rows = points_per_tile() / n;
    for (int axis = Dim - 1; axis >= 0; --axis) {
      contract_innermost(in, out, patterns, rows);
      patterns *= 2;
      rows /= n;
      std::swap(in, out);
    }
    for (int p = 0; p < rule_patterns; ++p) {
      for (int c = 0; c < Comp; ++c) result_[p][c] = in[p * Comp + c];
    }
  }

  static double max_abs_difference(const std::array<double, Comp>& a, const std::array<double, Comp>& b) {
    double largest = 0.0;
    for (int c = 0; c < Comp; ++c) {
      const double difference = std::abs(a[c] - b[c]);
      largest = (difference > largest || std::isnan(difference)) ? difference : largest;
    }
    return largest;
  }

  TileEstimate<Comp> summarize(const Box<Dim>& box) const {
    double volume_factor = 1.0;  // the Jacobian of [-1,1]^Dim -> box
    for (int d = 0; d < Dim; ++d) volume_factor *= 0.5 * (box.hi[d] - box.lo[d]);
    const std::array<double, Comp>& kronrod = result_[0];
    TileEstimate<Comp> tile;
    for (int c = 0; c < Comp; ++c) tile.value[c] = volume_factor * kronrod[c];
    tile.error = volume_factor * max_abs_difference(kronrod, result_[rule_patterns - 1]);
    double largest_indicator = -1.0;
    for (int d = 0; d < Dim; ++d) {
      const double indicator = max_abs_difference(kronrod, result_[1 << d]);
      if (indicator > largest_indicator) {
        largest_indicator = indicator;
        tile.split_dimension = d;
      }
    }
    return tile;
  }

  std::vector<double> samples_;  // [grid point, row-major][Comp]
  std::vector<double> scratch_;  // ping-pong partner of samples_ during contraction
  std::array<std::array<double, Comp>, rule_patterns> result_{};
};

}  // namespace pbrfit::integrate
