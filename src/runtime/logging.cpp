#include "pbrfit/runtime/logging.hpp"

#include <spdlog/pattern_formatter.h>
#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>

#include <chrono>

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

}  // namespace

void setup_logging(int rank, Verbosity verbosity) {
  auto logger = spdlog::stderr_logger_st("pbrfit");
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
