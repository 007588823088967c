#pragma once
// A neural stand-in for a measured material (Sztrajman et al. 2021; data/merl_nbrdf/README.md): a
// 6 -> 21 -> 21 -> 3 multilayer perceptron of the half/difference coordinates,
//   x = (sin th, 0, cos th, sin td cos pd, sin td sin pd, cos td),
//   y = max(exp(relu(relu(x W1 + b1) W2 + b2) W3 + b3) - 1, 0),
// whose output is the RGB BRDF value, MERL channel scales included.
//
// Invariants: the weights have the shapes above (NeuralBrdf's constructor throws std::invalid_argument
// otherwise); evaluate() is pure and its outputs are >= 0; tabulate() evaluates every cell centre of the
// MERL grid (merl_grid.hpp), so a stand-in is used exactly like a measured table.
#include <array>
#include <vector>

#include "pbrfit/brdf/merl_table.hpp"

namespace pbrfit::brdf {

struct NeuralBrdfWeights {
  std::vector<double> w1, b1, w2, b2, w3, b3;  // row-major kernels: input index major
};

class NeuralBrdf {
 public:
  explicit NeuralBrdf(NeuralBrdfWeights weights);
  std::array<double, 3> evaluate(const HalfDiff& angles) const;
  MerlTable tabulate() const;

 private:
  NeuralBrdfWeights w_;
};

}  // namespace pbrfit::brdf
