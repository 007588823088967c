#pragma once
// Job kind `ebrdf_render`: the reference renders and error tables of a finished `ebrdf` result
// (render_workload.hpp).
#include "pbrfit/jobs/job_kinds.hpp"

namespace pbrfit::jobs::ebrdf {

JobKind ebrdf_render_kind();

}  // namespace pbrfit::jobs::ebrdf
