#include "pbrfit/runtime/stop_signal.hpp"

#include <signal.h>

#include <atomic>
#include <cstdint>
#include <fstream>

namespace pbrfit::runtime {

namespace {

// The first stop signal and the pid that sent it, in one word so that a reader never sees one without the
// other: (pid << 8) | signal number; 0 while none has come.
std::atomic<std::int64_t> received{0};
static_assert(std::atomic<std::int64_t>::is_always_lock_free);

extern "C" void on_stop_signal(int signal, siginfo_t* info, void*) {
  const std::int64_t sender = info != nullptr && info->si_pid > 0 ? info->si_pid : 0;
  std::int64_t none = 0;
  received.compare_exchange_strong(none, (sender << 8) | signal);
}

int received_signal() { return int(received.load() & 0xff); }

}  // namespace

void install_stop_handlers() {
  struct sigaction action {};
  action.sa_sigaction = on_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART | SA_SIGINFO;
  for (int signal : {SIGTERM, SIGINT, SIGUSR1}) sigaction(signal, &action, nullptr);
}

bool stop_requested() { return received.load() != 0; }

void clear_stop_request() { received.store(0); }

const char* stop_signal_name() {
  switch (received_signal()) {
    case SIGTERM: return "SIGTERM";
    case SIGINT: return "SIGINT";
    case SIGUSR1: return "SIGUSR1";
    default: return "";
  }
}

long stop_signal_sender() { return long(received.load() >> 8); }

std::string stop_signal_origin() {
  std::string origin = stop_signal_name();
  const long sender = stop_signal_sender();
  if (origin.empty() || sender == 0) return origin;
  origin += " from process " + std::to_string(sender);
  std::ifstream comm("/proc/" + std::to_string(sender) + "/comm");
  std::string name;
  if (std::getline(comm, name) && !name.empty()) origin += " (" + name + ")";
  return origin;
}

}  // namespace pbrfit::runtime
