// Retries for about 2 s while the file is readable; the contract is in summary_reading.hpp.
#include "summary_reading.hpp"

#include <unistd.h>

#include <chrono>
#include <thread>

#include "pbrfit/core/error.hpp"
#include "pbrfit/store/checkpoint_file.hpp"

namespace pbrfit::cli {

namespace {

// The writer reopens the file at every flush; a read that lands mid-write is retried.
store::ResultSummary read_summary_retrying(const std::string& path) {
  for (int attempt = 0;; ++attempt) {
    try {
      return store::read_result_summary(path);
    } catch (const InputError&) {
      if (attempt >= 20 || access(path.c_str(), R_OK) != 0) throw;
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  }
}

}  // namespace

store::ResultSummary read_summary_or_explain(const std::string& path) {
  try {
    return read_summary_retrying(path);
  } catch (const InputError& error) {
    if (access(store::checkpoint_path_for(path).c_str(), R_OK) != 0) throw;
    throw InputError(error.where(), error.message() + "; its checkpoint is intact: `pbrfit run JOB --resume` rebuilds it");
  }
}

}  // namespace pbrfit::cli
