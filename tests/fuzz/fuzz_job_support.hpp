#pragma once
// The workload the checkpoint and journal targets check their input against: tests/fuzz/fuzz-dfg.yaml,
// the job whose interruption made their seeds (corpus/README.md), so that seeds pass the job-text check.
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include "pbrfit/jobs/job_kinds.hpp"
#include "pbrfit/runtime/workload.hpp"
#include "pbrfit/spec/job_spec.hpp"
#include "pbrfit/store/block_codec.hpp"

namespace pbrfit::fuzz {

struct FuzzJob {
  spec::JobSpec job;
  std::unique_ptr<runtime::Workload> workload;
  std::unique_ptr<store::BlockCodec> codec;
};

inline const FuzzJob& fuzz_job() {
  static const FuzzJob loaded = [] {
    FuzzJob f;
    f.job = spec::load_job_file(PBRFIT_SOURCE_DIR "/tests/fuzz/fuzz-dfg.yaml", jobs::kind_catalogue());
    f.workload = jobs::make_workload(f.job);
    f.codec = std::make_unique<store::BlockCodec>(f.workload->layout());
    return f;
  }();
  return loaded;
}

}  // namespace pbrfit::fuzz
