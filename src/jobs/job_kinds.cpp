#include "pbrfit/jobs/job_kinds.hpp"

#include <stdexcept>

#include "pbrfit/jobs/brdf/brdf_search_kind.hpp"
#include "pbrfit/jobs/ebrdf/ebrdf_kind.hpp"
#include "pbrfit/jobs/ebrdf/render_kind.hpp"
#include "pbrfit/jobs/lut/lut_kind.hpp"
#include "pbrfit/jobs/sweep/sweep_kind.hpp"
#include "pbrfit/jobs/symreg/symreg_kind.hpp"

namespace pbrfit::jobs {

const std::vector<JobKind>& job_kinds() {
  static const std::vector<JobKind> kinds = {lut::lut_kind(), sweep::sweep_kind(), symreg::symreg_kind(),
                                              brdf::brdf_search_kind(), ebrdf::ebrdf_kind(),
                                              ebrdf::ebrdf_render_kind()};
  return kinds;
}

namespace {

const JobKind& find_kind(const std::string& name) {
  for (const auto& kind : job_kinds())
    if (kind.name == name) return kind;
  throw std::logic_error("unregistered job kind " + name);
}

}  // namespace

spec::KindCatalogue kind_catalogue() {
  spec::KindCatalogue catalogue;
  for (const auto& kind : job_kinds()) catalogue.names.push_back(kind.name);
  catalogue.schema_for = [](const std::string& name) -> const spec::Schema& { return find_kind(name).schema; };
  return catalogue;
}

std::unique_ptr<runtime::Workload> make_workload(const spec::JobSpec& job) {
  return find_kind(job.kind).make_workload(job);
}

}  // namespace pbrfit::jobs
