#pragma once
// SIGTERM, SIGINT and SIGUSR1 request a stop at the next safe point (between work items).
namespace pbrfit::runtime {

void install_stop_handlers();
bool stop_requested();
// The name of the first signal received, e.g. "SIGTERM"; "" when none.
const char* stop_signal_name();
// Forgets a received signal: for a process that runs several jobs one after another (tests).
void clear_stop_request();

}  // namespace pbrfit::runtime
