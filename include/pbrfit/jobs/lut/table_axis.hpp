#pragma once
// Sample positions of a table axis over [0, 1]: cell centres (i + 0.5) / n or edges i / (n - 1).
#include <string>
#include <vector>

namespace pbrfit::jobs::lut {

enum class Placement { centres, edges };

std::vector<double> unit_axis(std::size_t count, Placement placement);

}  // namespace pbrfit::jobs::lut
