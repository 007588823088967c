#include <cstring>

#include "pbrfit/cli/commands.hpp"
#include "pbrfit/runtime/stop_signal.hpp"

// A run catches stop signals from its first instruction: a signal before any work still ends it through
// the one exit path (75 once the job has started). Other commands keep the default action, so a stuck
// `validate` or `status` can still be interrupted.
int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "run") == 0) pbrfit::runtime::install_stop_handlers();
  return pbrfit::cli::main_entry(argc, argv);
}
