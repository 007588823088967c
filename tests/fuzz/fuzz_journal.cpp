// Block journals (`R.h5.journal`): every block replayed as `run --resume` rebuilds the result from them.
#include "fuzz_job_support.hpp"
#include "fuzz_support.hpp"
#include "pbrfit/store/block_journal.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& job = pbrfit::fuzz::fuzz_job();
  const auto& path = pbrfit::fuzz::scratch_file(data, size, ".journal");
  pbrfit::fuzz::expect_result_or_input_error([&] {
    pbrfit::store::replay_block_journal(path, job.job.text, *job.codec, size, [](pbrfit::store::Block) {});
  });
  return 0;
}
