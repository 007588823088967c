#pragma once
// Job kind `lut`: reference tables computed by deterministic adaptive integration, one work item per
// table row. Functions: `dfg` (the split-sum environment BRDF table).
#include "pbrfit/jobs/job_kinds.hpp"

namespace pbrfit::jobs::lut {

JobKind lut_kind();

}  // namespace pbrfit::jobs::lut
