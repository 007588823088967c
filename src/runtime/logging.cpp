#include "pbrfit/runtime/logging.hpp"

#include <spdlog/pattern_formatter.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <memory>

#include "terminal_sink.hpp"

namespace pbrfit::runtime {

namespace {

const auto process_start = std::chrono::steady_clock::now();

class ElapsedFlag final : public spdlog::custom_flag_formatter {
 public:
  void format(const spdlog::details::log_msg&, const std::tm&, spdlog::memory_buf_t& dest) override {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - process_start).count();
    char text[32];
    const int n = std::snprintf(text, sizeof text, "%8.1fs", s);
    dest.append(text, text + n);
  }
  std::unique_ptr<custom_flag_formatter> clone() const override { return std::make_unique<ElapsedFlag>(); }
};

std::shared_ptr<TerminalSink> terminal;

}  // namespace

void TerminalSink::sink_it_(const spdlog::details::log_msg& message) {
  spdlog::memory_buf_t text;
  formatter_->format(message, text);
  if (progress_shown_) std::fputs("\r\x1b[K", stderr);
  std::size_t size = text.size();
  progress_shown_ = progress_next_;
  if (progress_next_ && size > 0 && text.data()[size - 1] == '\n') --size;  // in place: no newline
  progress_next_ = false;
  std::fwrite(text.data(), 1, size, stderr);
  std::fflush(stderr);
}

void TerminalSink::flush_() { std::fflush(stderr); }

void log_progress(const std::string& line) {
  if (terminal) terminal->mark_progress();
  spdlog::info("{}", line);
}

void setup_logging(int rank, Verbosity verbosity) {
  terminal = std::make_shared<TerminalSink>(rank == 0 && isatty(STDERR_FILENO) == 1);
  auto logger = std::make_shared<spdlog::logger>("pbrfit", terminal);
  auto formatter = std::make_unique<spdlog::pattern_formatter>();
  formatter->add_flag<ElapsedFlag>('*').set_pattern("[%* r" + std::to_string(rank) + "] %l: %v");
  logger->set_formatter(std::move(formatter));
  spdlog::level::level_enum level = spdlog::level::info;
  if (verbosity == Verbosity::quiet) level = spdlog::level::warn;
  if (verbosity == Verbosity::verbose) level = spdlog::level::debug;
  if (rank != 0 && verbosity != Verbosity::verbose) level = spdlog::level::warn;
  logger->set_level(level);
  logger->flush_on(spdlog::level::trace);
  spdlog::set_default_logger(std::move(logger));
}

}  // namespace pbrfit::runtime
