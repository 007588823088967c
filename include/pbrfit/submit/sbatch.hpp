#pragma once
// Runs `sbatch --parsable SCRIPT` directly (no shell) and returns the Slurm job id.
#include <string>

namespace pbrfit::submit {

// Throws RunError with sbatch's own message when submission fails or sbatch is missing.
std::string run_sbatch(const std::string& script_path);

}  // namespace pbrfit::submit
