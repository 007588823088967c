#pragma once
// Job kind `ebrdf`: LTC mip hierarchies that prefilter a normal map under area lights (Nahmias 2022),
// fitted per mip texel, view and component, tiles as work items.
#include "pbrfit/jobs/job_kinds.hpp"

namespace pbrfit::jobs::ebrdf {

JobKind ebrdf_kind();

}  // namespace pbrfit::jobs::ebrdf
