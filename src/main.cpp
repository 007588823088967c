#include "pbrfit/cli/commands.hpp"
#include "pbrfit/runtime/stop_signal.hpp"

// Stop signals are caught from the first instruction on: a signal before any work still ends the process
// through the one exit path (75 once the job has started; see runtime/stop_signal.hpp).
int main(int argc, char** argv) {
  pbrfit::runtime::install_stop_handlers();
  return pbrfit::cli::main_entry(argc, argv);
}
