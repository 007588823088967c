// Job files: the YAML reader, the common keys and the whole validation of every kind's section, down to
// the workload the job would run (expressions, grids, data files named by the job), as `pbrfit validate`.
#include "fuzz_support.hpp"
#include "pbrfit/jobs/job_kinds.hpp"
#include "pbrfit/spec/job_spec.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const auto kinds = pbrfit::jobs::kind_catalogue();
  pbrfit::fuzz::expect_result_or_input_error([&] {
    const auto job = pbrfit::spec::parse_job_text(std::string(pbrfit::fuzz::text_of(data, size)), "fuzz.yaml", kinds);
    const auto workload = pbrfit::jobs::make_workload(job);
    for (std::uint32_t stage = 0; stage < workload->stage_count(); ++stage) (void)workload->item_count(stage);
    (void)workload->layout();
  });
  return 0;
}
