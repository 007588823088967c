// Checkpoint files (`R.h5.checkpoint`): the record log, the state it spells, and the check of that state
// against the job's workload that `run --resume` makes before it touches anything.
#include "fuzz_job_support.hpp"
#include "fuzz_support.hpp"
#include "pbrfit/store/checkpoint_file.hpp"
#include "resumption.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& job = pbrfit::fuzz::fuzz_job();
  const auto& path = pbrfit::fuzz::scratch_file(data, size, ".checkpoint");
  pbrfit::fuzz::expect_result_or_input_error([&] {
    const auto reading = pbrfit::store::read_checkpoint(path);
    pbrfit::runtime::check_checkpoint(path, reading.state, *job.workload, *job.codec);
  });
  return 0;
}
