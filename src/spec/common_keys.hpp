#pragma once
#include "pbrfit/spec/job_spec.hpp"

namespace pbrfit::spec {

// Fills the common keys of spec from the validated top-level section (validated against
// common_schema() plus the kind's section), applying the checks a schema cannot express: the name's
// characters and length, output's suffix, the time limit's format. Throws InputError.
void read_common_keys(const Section& job, JobSpec& spec);

}  // namespace pbrfit::spec
