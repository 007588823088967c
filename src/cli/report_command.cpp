// `pbrfit report RESULT.h5 [--out DIR] [--watch SECONDS]`: checks here that RESULT is a readable pbrfit result (the same
// one-line refusals as `status`, exit 2), then runs the report package ($PBRFIT_REPORT_DIR, else report/ in
// the share directory of store/share_directory.hpp) with /usr/bin/python3 (or $PBRFIT_PYTHON), isolated
// from the user's Python settings, and returns its exit code: 0, 2 or 3 with its own one-line message. An
// interpreter that is missing, a package that is not there, or a script that ends any other way is exit 3,
// one line.
#include <unistd.h>

#include <cstdlib>

#include "child_process.hpp"
#include "exit_on_error.hpp"
#include "summary_reading.hpp"
#include "pbrfit/cli/commands.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/core/quoted_text.hpp"
#include "pbrfit/store/share_directory.hpp"

namespace pbrfit::cli {

namespace {

constexpr const char* default_python = "/usr/bin/python3";  // the interpreter Debian's h5py is built for

std::string setting(const char* variable, const char* fallback) {
  const char* value = std::getenv(variable);
  return value && *value ? value : fallback;
}

std::string report_package() {
  std::string directory = setting("PBRFIT_REPORT_DIR", "");
  if (directory.empty()) directory = store::share_directory() + "/report";
  if (access((directory + "/__main__.py").c_str(), R_OK) != 0)
    throw RunError("the report package is missing: no " + quote(directory + "/__main__.py"));
  return directory;
}

// -B: no bytecode files in the source tree; -E, -s: no PYTHON* variables, no user site packages.
std::vector<std::string> report_arguments(const ReportOptions& options) {
  std::vector<std::string> argv = {setting("PBRFIT_PYTHON", default_python), "-B", "-E", "-s", report_package()};
  if (!options.out_dir.empty()) argv.push_back("--out=" + options.out_dir);
  if (options.watch_seconds > 0) argv.push_back("--watch=" + std::to_string(options.watch_seconds));
  argv.insert(argv.end(), {"--", options.result_file});
  return argv;
}

int exit_code_of(const ChildExit& child, const std::string& python) {
  if (!child.signalled && (child.code == exit_success || child.code == exit_invalid_input || child.code == exit_run_failure))
    return child.code;
  throw RunError("the report script (" + quote(python) + ") ended " +
                 (child.signalled ? "by signal " : "with exit code ") + std::to_string(child.code));
}

}  // namespace

int report_command(const ReportOptions& options) {
  return exit_on_error([&] {
    read_summary_or_explain(options.result_file);
    const auto argv = report_arguments(options);
    return exit_code_of(run_program(argv), argv[0]);
  });
}

}  // namespace pbrfit::cli
