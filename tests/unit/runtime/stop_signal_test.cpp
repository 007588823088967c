// The stop signal remembers the first signal and who sent it, so that a log can say where a stop came from.
#include "pbrfit/runtime/stop_signal.hpp"

#include <unistd.h>

#include <catch2/catch_test_macros.hpp>
#include <csignal>
#include <fstream>
#include <string>

using namespace pbrfit;

namespace {

std::string own_process_name() {
  std::ifstream comm("/proc/self/comm");
  std::string name;
  std::getline(comm, name);
  return name;
}

}  // namespace

TEST_CASE("a stop signal is named with the process that sent it, and only the first one counts", "[runtime]") {
  runtime::install_stop_handlers();
  runtime::clear_stop_request();
  CHECK_FALSE(runtime::stop_requested());
  CHECK(runtime::stop_signal_origin().empty());
  CHECK(runtime::stop_signal_sender() == 0);

  REQUIRE(::kill(::getpid(), SIGUSR1) == 0);  // delivered before kill() returns: it targets this process
  REQUIRE(runtime::stop_requested());
  CHECK(std::string(runtime::stop_signal_name()) == "SIGUSR1");
  CHECK(runtime::stop_signal_sender() == long(::getpid()));
  CHECK(runtime::stop_signal_origin() ==
        "SIGUSR1 from process " + std::to_string(::getpid()) + " (" + own_process_name() + ")");

  REQUIRE(::kill(::getpid(), SIGTERM) == 0);
  CHECK(std::string(runtime::stop_signal_name()) == "SIGUSR1");

  runtime::clear_stop_request();
  CHECK_FALSE(runtime::stop_requested());
  CHECK(runtime::stop_signal_origin().empty());
}
