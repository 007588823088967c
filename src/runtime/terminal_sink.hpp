#pragma once
// Where log lines go: standard error. On a terminal the progress line is written in place (carriage
// return, erase line, no newline) and the next line of any kind replaces it, so a running job shows one
// updating progress line between its other messages; elsewhere (files, pipes, Slurm logs) every line is
// kept. Private to the runtime.
#include <spdlog/details/null_mutex.h>
#include <spdlog/sinks/base_sink.h>

namespace pbrfit::runtime {

class TerminalSink final : public spdlog::sinks::base_sink<spdlog::details::null_mutex> {
 public:
  explicit TerminalSink(bool in_place) : in_place_(in_place) {}
  // The next message is a progress line.
  void mark_progress() { progress_next_ = in_place_; }

 protected:
  void sink_it_(const spdlog::details::log_msg& message) override;
  void flush_() override;

 private:
  bool in_place_;
  bool progress_next_ = false;
  bool progress_shown_ = false;
};

// Logs a progress line at info level, in place on a terminal.
void log_progress(const std::string& line);

}  // namespace pbrfit::runtime
