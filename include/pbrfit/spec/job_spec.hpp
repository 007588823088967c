#pragma once
// A job file: the common keys every kind shares, plus the validated section named after its kind.
//
//   name: dfg-quickstart          # required, [A-Za-z0-9._-]+
//   kind: lut                     # required, one of the registered kinds
//   seed: 1                       # default 0; random streams derive from (seed, work item)
//   output: results/x.h5          # default results/<name>.h5
//   checkpoint: {interval_seconds: 30, interval_items: 0}   # whichever comes first; 0 disables
//   resources: {ranks: 2, threads: 1, time_limit: "01:00:00", partition: "", account: ""}
//   lut: {...}                    # the kind's own section
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pbrfit/spec/schema.hpp"

namespace pbrfit::spec {

struct CheckpointPolicy {
  double interval_seconds = 30.0;    // 0: never by time
  std::int64_t interval_items = 0;   // 0: never by count
};

struct Resources {
  int ranks = 2;
  int threads = 1;  // compute threads per rank (CPUs per Slurm task)
  std::string time_limit = "01:00:00";  // Slurm format: see parse_slurm_time_limit
  double time_limit_seconds = 3600.0;
  std::string partition;
  std::string account;
};

struct JobSpec {
  std::string file;   // path as given
  std::string text;   // the complete job text, byte for byte
  std::string name;
  std::string kind;
  std::uint64_t seed = 0;
  std::string output;
  CheckpointPolicy checkpoint;
  Resources resources;
  Section kind_section;  // the validated section named after the kind
};

// The registered kinds, for validation: kind name -> schema of its section.
struct KindCatalogue {
  std::vector<std::string> names;
  std::function<const Schema&(const std::string& kind)> schema_for;
};

// The largest job file pbrfit reads (256 KiB): job files describe work, they do not carry data.
inline constexpr std::size_t max_job_file_bytes = std::size_t(256) << 10;

// Parses and validates; throws InputError (FILE:LINE:COL) on any problem, including unreadable files,
// files that are not regular files, and files larger than max_job_file_bytes.
JobSpec load_job_file(const std::string& path, const KindCatalogue& kinds);
JobSpec parse_job_text(const std::string& text, const std::string& file, const KindCatalogue& kinds);

// The schema of the common keys (without the kind sections), for documentation and tests.
const Schema& common_schema();

// Seconds in a Slurm time limit: MM, MM:SS, HH:MM:SS, D-HH, D-HH:MM or D-HH:MM:SS. The leading field
// (minutes, hours or days) has 1 to 9 digits, the others 1 or 2 digits, with minutes and seconds below
// 60 after it and hours below 24 after days. nullopt when malformed; "0" gives 0 (job files reject it).
std::optional<std::int64_t> parse_slurm_time_limit(const std::string& text);

}  // namespace pbrfit::spec
