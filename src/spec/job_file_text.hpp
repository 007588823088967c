#pragma once
// The text of a job file: a regular file of at most max_job_file_bytes (job_spec.hpp), read whole.
// Throws InputError naming the file otherwise. Private to spec.
#include <string>

namespace pbrfit::spec {

std::string read_job_file_text(const std::string& path);

}  // namespace pbrfit::spec
