#pragma once
// Job kind `brdf_search`: genBRDF (Brady et al. 2014) - an island GP over edits of a seed BRDF, scored by
// the precomputed light-weighted metric against measured materials, then an evaluation of the seed and
// the found BRDFs on the training and testing materials (docs/job-files.md, kind `brdf_search`;
// docs/results-brdf_search.md).
#include "pbrfit/jobs/brdf/brdf_search_settings.hpp"
#include "pbrfit/jobs/job_kinds.hpp"

namespace pbrfit::jobs::brdf {

JobKind brdf_search_kind();
const spec::Schema& brdf_search_schema();
// Loads the materials and builds the scene. Throws InputError at the offending key for inconsistent
// settings, unknown materials or unreadable data.
BrdfSearchSettings brdf_search_settings(const spec::Section& section);

}  // namespace pbrfit::jobs::brdf
