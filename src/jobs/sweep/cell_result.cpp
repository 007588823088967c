#include "pbrfit/jobs/sweep/cell_result.hpp"

#include "pbrfit/core/error.hpp"

namespace pbrfit::jobs::sweep {

void require_shapes(const CellFits& fits, const std::vector<FitShape>& shapes) {
  if (fits.size() != shapes.size()) throw RunError("a sweep cell result holds another number of models");
  for (std::size_t m = 0; m < shapes.size(); ++m) {
    const ModelFit& fit = fits[m];
    if (static_cast<std::uint8_t>(fit.start) > 3 || fit.parameters.size() != shapes[m].parameters ||
        fit.outputs.size() != shapes[m].outputs)
      throw RunError("a sweep cell result does not match the job's models");
  }
}

}  // namespace pbrfit::jobs::sweep
