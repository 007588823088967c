#include "pbrfit/submit/batch_script.hpp"

#include <algorithm>
#include <filesystem>

#include "pbrfit/core/error.hpp"
#include "pbrfit/core/quoted_text.hpp"

namespace pbrfit::submit {

namespace {

// Characters allowed where a value is written into a #SBATCH line, which no shell quoting protects.
bool safe_for_directive(const std::string& text, const std::string& extra) {
  return std::all_of(text.begin(), text.end(), [&](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-' ||
           extra.find(c) != std::string::npos;
  });
}

void require_safe(const spec::JobSpec& job, const std::string& what, const std::string& value,
                  const std::string& extra) {
  if (!safe_for_directive(value, extra))
    throw InputError({job.file}, what + " " + quote(value) + " may contain only letters, digits and ._-" + extra +
                                     " to go into a Slurm batch script");
}

std::string absolute(const std::string& path, const std::string& workdir) {
  const std::filesystem::path p(path);
  return (p.is_absolute() ? p : std::filesystem::path(workdir) / p).lexically_normal().string();
}

// Slurm's early warning is delivered with up to a minute's slack; a tenth of the limit, within [60, 600] s.
int warning_seconds_for(double limit_seconds) {
  return int(std::clamp(limit_seconds / 10.0, 60.0, 600.0));
}

std::string log_path_for(const std::string& output) {
  const std::filesystem::path p(output);
  return (p.parent_path() / (p.stem().string() + ".slurm-%j.log")).string();
}

}  // namespace

std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

BatchJob batch_job_for(const spec::JobSpec& job, const ResourceOverrides& overrides, const std::string& pbrfit,
                       const std::string& workdir) {
  BatchJob b;
  b.name = job.name;
  b.ranks = overrides.ranks > 0 ? overrides.ranks : job.resources.ranks;
  b.threads = overrides.threads > 0 ? overrides.threads : job.resources.threads;
  b.launcher = "srun --mpi=pmix --cpus-per-task=" + std::to_string(b.threads);
  b.time_limit = overrides.time_limit.empty() ? job.resources.time_limit : overrides.time_limit;
  b.time_limit_seconds = job.resources.time_limit_seconds;
  if (!overrides.time_limit.empty()) {
    const auto seconds = spec::parse_slurm_time_limit(overrides.time_limit);
    if (!seconds) throw InputError({"--time"}, quote(overrides.time_limit) + " is not a Slurm time limit");
    if (*seconds == 0)
      throw InputError({"--time"}, quote(overrides.time_limit) + " is zero, which Slurm reads as no limit at all");
    b.time_limit_seconds = double(*seconds);
  }
  b.warning_seconds = warning_seconds_for(b.time_limit_seconds);
  b.partition = overrides.partition.empty() ? job.resources.partition : overrides.partition;
  b.account = overrides.account.empty() ? job.resources.account : overrides.account;
  b.job_file = absolute(job.file, workdir);
  b.output = absolute(job.output, workdir);
  b.log = log_path_for(b.output);
  b.script = absolute(job.output + ".sbatch", workdir);
  b.workdir = workdir;
  b.pbrfit = pbrfit;
  require_safe(job, "the time limit", b.time_limit, ":");
  require_safe(job, "the partition", b.partition, ",");
  require_safe(job, "the account", b.account, "");
  require_safe(job, "the log path", b.log, "/%+");
  require_safe(job, "the working directory", b.workdir, "/+");
  return b;
}

std::string render_template(const std::string& text, const std::map<std::string, std::string>& values,
                            const std::string& template_path) {
  std::string out;
  std::size_t pos = 0;
  int line = 1;
  while (pos < text.size()) {
    const auto open = text.find("{{", pos);
    const auto chunk_end = open == std::string::npos ? text.size() : open;
    line += int(std::count(text.begin() + std::ptrdiff_t(pos), text.begin() + std::ptrdiff_t(chunk_end), '\n'));
    out.append(text, pos, chunk_end - pos);
    if (open == std::string::npos) break;
    const auto close = text.find("}}", open);
    if (close == std::string::npos) throw InputError({template_path, line}, "unclosed '{{' in the batch template");
    const std::string key = text.substr(open + 2, close - open - 2);
    const auto value = values.find(key);
    if (value == values.end())
      throw InputError({template_path, line}, "unknown placeholder '{{" + key + "}}' in the batch template");
    out += value->second;
    pos = close + 2;
  }
  return out;
}

std::string render_batch_script(const BatchJob& job, const std::string& template_text,
                                const std::string& template_path) {
  const auto directive = [](const std::string& option, const std::string& value) {
    return value.empty() ? "# (no " + option + ")" : "#SBATCH --" + option + "=" + value;
  };
  const std::map<std::string, std::string> values = {
      {"name", job.name},
      {"ranks", std::to_string(job.ranks)},
      {"threads", std::to_string(job.threads)},
      {"time_limit", job.time_limit},
      {"warning_seconds", std::to_string(job.warning_seconds)},
      {"partition_directive", directive("partition", job.partition)},
      {"account_directive", directive("account", job.account)},
      {"log", job.log},
      {"workdir", job.workdir},
      {"launcher", job.launcher},
      {"pbrfit", shell_quote(job.pbrfit)},
      {"job_file", shell_quote(job.job_file)},
      {"output", shell_quote(job.output)},
  };
  return render_template(template_text, values, template_path);
}

}  // namespace pbrfit::submit
