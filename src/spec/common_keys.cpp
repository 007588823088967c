#include "common_keys.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>

#include "message_text.hpp"

namespace pbrfit::spec {
namespace {

constexpr std::size_t max_name_length = 100;
constexpr const char* time_limit_forms = "MM, MM:SS, HH:MM:SS, D-HH, D-HH:MM or D-HH:MM:SS";

Schema checkpoint_schema() {
  Schema schema("checkpoint");
  schema.number("interval_seconds", "Save a checkpoint at least this often, in seconds; 0: never.")
      .defaults_to(30.0)
      .at_least(0);
  schema.integer("interval_items", "Save a checkpoint after this many finished work items; 0: never.")
      .defaults_to(0)
      .at_least(0);
  return schema;
}

Schema resources_schema() {
  Schema schema("resources");
  schema.integer("ranks", "MPI ranks to run with.").defaults_to(2).range(1, 65536);
  schema.integer("threads", "Compute threads per rank: the CPUs each Slurm task asks for.").defaults_to(1).range(1, 1024);
  schema.string("time_limit", std::string("Wall-clock limit in Slurm form: ") + time_limit_forms + ".")
      .defaults_to("01:00:00");
  schema.string("partition", "Slurm partition; empty: the cluster's default.").defaults_to("");
  schema.string("account", "Slurm account; empty: the user's default.").defaults_to("");
  return schema;
}

Schema make_common_schema() {
  Schema schema("job");
  schema.string("name", "The job's name: letters, digits, '.', '_' and '-', starting with a letter or digit, at most 100 characters.")
      .require();
  schema.string("kind", "The kind of job; selects the section named after it.").require();
  schema.integer("seed", "Random streams derive from (seed, work item).").defaults_to(0).at_least(0);
  schema.string("output", "The HDF5 result file, ending in .h5; default results/<name>.h5.");
  schema.section("checkpoint", checkpoint_schema(), "When to save checkpoints; whichever comes first.");
  schema.section("resources", resources_schema(), "What to ask the batch system for.");
  return schema;
}

bool is_name_character(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
         c == '_' || c == '-';
}

std::string checked_name(const Section& job) {
  const std::string& name = job.get_string("name");
  if (name.empty()) job.reject("name", "must not be empty");
  if (!std::isalnum(static_cast<unsigned char>(name.front())))
    job.reject("name", "must start with a letter or a digit, got " + quote(name));
  if (!std::ranges::all_of(name, is_name_character)) {
    job.reject("name", "may contain only letters, digits, '.', '_' and '-', got " + quote(name));
  }
  if (name.size() > max_name_length) {
    job.reject("name", "must be at most " + std::to_string(max_name_length) + " characters long, got " +
                           std::to_string(name.size()));
  }
  return name;
}

std::string checked_output(const Section& job, const std::string& name) {
  if (!job.has("output")) return "results/" + name + ".h5";
  const std::string& output = job.get_string("output");
  if (output.empty()) job.reject("output", "must not be empty");
  if (has_control_character(output))
    job.reject("output", "must not contain control characters (such as NUL or a newline), got " + quote(output));
  if (!output.ends_with(".h5")) job.reject("output", "must end in .h5, got " + quote(output));
  return output;
}

CheckpointPolicy read_checkpoint(const Section& checkpoint) {
  return CheckpointPolicy{.interval_seconds = checkpoint.get_number("interval_seconds"),
                          .interval_items = checkpoint.get_int("interval_items")};
}

Resources read_resources(const Section& resources) {
  const std::string& time_limit = resources.get_string("time_limit");
  const std::optional<std::int64_t> seconds = parse_slurm_time_limit(time_limit);
  if (!seconds) {
    resources.reject("time_limit", std::string("must be a Slurm time limit (") + time_limit_forms +
                                       "), got " + quote(time_limit));
  }
  if (*seconds == 0) resources.reject("time_limit", "must be longer than zero, got " + quote(time_limit));
  return Resources{.ranks = static_cast<int>(resources.get_int("ranks")),
                   .threads = static_cast<int>(resources.get_int("threads")),
                   .time_limit = time_limit,
                   .time_limit_seconds = static_cast<double>(*seconds),
                   .partition = resources.get_string("partition"),
                   .account = resources.get_string("account")};
}

}  // namespace

const Schema& common_schema() {
  static const Schema schema = make_common_schema();
  return schema;
}

void read_common_keys(const Section& job, JobSpec& spec) {
  spec.name = checked_name(job);
  spec.kind = job.get_string("kind");
  spec.seed = static_cast<std::uint64_t>(job.get_int("seed"));
  spec.output = checked_output(job, spec.name);
  spec.checkpoint = read_checkpoint(job.get_section("checkpoint"));
  spec.resources = read_resources(job.get_section("resources"));
}

}  // namespace pbrfit::spec
