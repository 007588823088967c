#pragma once
// Job kind `symreg`: symbolic regression by island-model linear genetic programming, a Pareto front of error
// vs shader cost per output, with constant fitting and reference anchors (docs/job-files.md, kind
// `symreg`; docs/results-symreg.md).
#include "pbrfit/jobs/job_kinds.hpp"
#include "pbrfit/jobs/symreg/symreg_settings.hpp"

namespace pbrfit::jobs::symreg {

JobKind symreg_kind();
const spec::Schema& symreg_schema();
// Throws InputError at the offending key for inconsistent settings or unreadable data.
SymregSettings symreg_settings(const spec::Section& symreg);

}  // namespace pbrfit::jobs::symreg
