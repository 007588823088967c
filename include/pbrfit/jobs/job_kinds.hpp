#pragma once
// The registry of job kinds: each has a name, the schema of its YAML section and a factory that turns
// a validated job into a Workload for the runtime.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "pbrfit/runtime/workload.hpp"
#include "pbrfit/spec/job_spec.hpp"

namespace pbrfit::jobs {

struct JobKind {
  std::string name;
  std::string summary;
  spec::Schema schema;
  // Throws InputError (at the offending key) for settings that are individually valid but inconsistent.
  std::function<std::unique_ptr<runtime::Workload>(const spec::JobSpec&)> make_workload;
};

const std::vector<JobKind>& job_kinds();
spec::KindCatalogue kind_catalogue();
std::unique_ptr<runtime::Workload> make_workload(const spec::JobSpec& job);

}  // namespace pbrfit::jobs
