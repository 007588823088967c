#include "progress_log.hpp"

#include <spdlog/spdlog.h>

#include "duration_text.hpp"
#include "terminal_sink.hpp"

namespace pbrfit::runtime {

ProgressLog::ProgressLog(const Workload& workload, double interval_seconds, std::uint64_t done_at_start)
    : workload_(workload),
      interval_seconds_(interval_seconds),
      items_total_(workload.total_items()),
      done_at_start_(done_at_start) {}

void ProgressLog::maybe_log(const RunState& state) {
  if (!work_at_start_) work_at_start_ = workload_.work_done(state.summary());  // the first call comes before any work
  const auto now = Clock::now();
  if (std::chrono::duration<double>(now - last_).count() < interval_seconds_) return;
  last_ = now;
  const auto done = state.items_done();
  const double run_seconds = std::chrono::duration<double>(now - started_).count();
  const double rate = double(done - done_at_start_) / std::max(run_seconds, 1e-9);
  const double eta = rate > 0 ? double(items_total_ - done) / rate : 0.0;
  const std::string unit = workload_.work_unit();
  const std::string work_rate =
      unit.empty() ? "" : fmt::format(", {:.3g} {}/s", (workload_.work_done(state.summary()) - *work_at_start_) /
                                                         std::max(run_seconds, 1e-9), unit);
  log_progress(fmt::format("{:5.1f}% ({}/{} items, {:.1f} items/s{}, ETA {}) {}", 100.0 * double(done) / double(items_total_),
                           done, items_total_, rate, work_rate, rate > 0 ? duration_text(eta) : "unknown",
                           workload_.headline(state.summary())));
}

}  // namespace pbrfit::runtime
