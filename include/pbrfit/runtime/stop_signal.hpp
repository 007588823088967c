#pragma once
// SIGTERM, SIGINT and SIGUSR1 request a stop at the next safe point (between work items).
#include <string>

namespace pbrfit::runtime {

void install_stop_handlers();
bool stop_requested();
// The name of the first signal received, e.g. "SIGTERM"; "" when none.
const char* stop_signal_name();
// The pid that sent that signal (0 when unknown: none yet, or sent by the kernel or the terminal driver).
long stop_signal_sender();
// What the logs say of the stop: "SIGTERM from process 4242 (slurmstepd)", or just the name when the
// sender is unknown or has gone; "" when no signal came. Reads /proc: not for a signal handler.
std::string stop_signal_origin();
// Forgets a received signal: for a process that runs several jobs one after another (tests).
void clear_stop_request();

}  // namespace pbrfit::runtime
