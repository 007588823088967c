#include "pbrfit/jobs/lut/table_axis.hpp"

namespace pbrfit::jobs::lut {

std::vector<double> unit_axis(std::size_t count, Placement placement) {
  std::vector<double> values(count);
  for (std::size_t i = 0; i < count; ++i)
    values[i] = placement == Placement::centres ? (double(i) + 0.5) / double(count)
                                                : double(i) / double(count - 1);
  return values;
}

}  // namespace pbrfit::jobs::lut
