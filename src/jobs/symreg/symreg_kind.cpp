#include "pbrfit/jobs/symreg/symreg_kind.hpp"

#include "pbrfit/jobs/symreg/symreg_workload.hpp"

namespace pbrfit::jobs::symreg {
namespace {

std::unique_ptr<runtime::Workload> make_symreg(const spec::JobSpec& job) {
  return std::make_unique<SymregWorkload>(symreg_settings(job.kind_section));
}

}  // namespace

JobKind symreg_kind() {
  return {"symreg", "symbolic regression: island-model linear GP, Pareto fronts of error vs shader cost",
          symreg_schema(), make_symreg};
}

}  // namespace pbrfit::jobs::symreg
