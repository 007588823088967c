#pragma once
// Job kind `sweep`: hierarchical parameter sweeps. For every cell of a grid over the problem's axes, each
// model is fitted to the problem's target by Differential Evolution and Nelder-Mead, warm-started from
// coarser levels and from already fitted neighbours (docs/job-files.md, docs/results-sweep.md).
#include "pbrfit/jobs/job_kinds.hpp"
#include "pbrfit/jobs/sweep/sweep_settings.hpp"

namespace pbrfit::jobs::sweep {

JobKind sweep_kind();

// The settings of a validated `sweep` section (its keys: sweep_keys.hpp); throws InputError at the offending key for settings that
// are individually valid but inconsistent (an axis the problem does not have, too many levels, ...).
SweepSettings sweep_settings(const spec::Section& sweep);

}  // namespace pbrfit::jobs::sweep
