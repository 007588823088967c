#pragma once
// The prefiltered tables of a finished `ebrdf` job, read back from its result file for rendering: the
// MIP-0 normal map, the specular GGX width and the LTC mip hierarchy of each component it holds.
//
// Contract: load_prefiltered_tables throws InputError naming the file when it is not a complete ebrdf
// result with both components (another kind, still running, or one component only); the hierarchies hold
// every level from 1 to the coarsest the job fitted.
#include <memory>
#include <optional>
#include <string>

#include "pbrfit/ebrdf/mip_tables.hpp"
#include "pbrfit/ebrdf/normal_map.hpp"

namespace pbrfit::jobs::ebrdf {

struct PrefilteredTables {
  std::shared_ptr<const pbrfit::ebrdf::NormalMap> map;
  double alpha = 0.01;
  std::optional<pbrfit::ebrdf::LtcMipTables> specular;
  std::optional<pbrfit::ebrdf::LtcMipTables> diffuse;
};

PrefilteredTables load_prefiltered_tables(const std::string& path);

}  // namespace pbrfit::jobs::ebrdf
