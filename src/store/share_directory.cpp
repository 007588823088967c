#include "pbrfit/store/share_directory.hpp"

#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "pbrfit/core/error.hpp"

namespace pbrfit::store {
namespace {

namespace fs = std::filesystem;

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value && *value ? value : "";
}

fs::path program_directory() {
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  return error ? fs::path() : program.parent_path();
}

}  // namespace

std::string share_directory() {
  if (std::string set = environment("PBRFIT_SHARE_DIR"); !set.empty()) return set;
  fs::path directory = program_directory();
  std::string looked;
  for (int level = 0; level < 4 && !directory.empty(); ++level) {
    const fs::path candidate = directory / "share" / "pbrfit";
    std::error_code error;
    if (fs::is_directory(candidate, error)) return fs::canonical(candidate, error).string();
    looked += (looked.empty() ? "" : ", ") + candidate.string();
    if (directory == directory.parent_path()) break;
    directory = directory.parent_path();
  }
  throw RunError("pbrfit's shared files are not installed: no share/pbrfit beside the program (looked in " +
                 (looked.empty() ? std::string("nothing: the program's path is unknown") : looked) +
                 "); set PBRFIT_SHARE_DIR to the folder that holds data/, report/ and sbatch.template");
}

std::string data_directory() {
  if (std::string set = environment("PBRFIT_DATA_DIR"); !set.empty()) return set;
  return share_directory() + "/data";
}

}  // namespace pbrfit::store
