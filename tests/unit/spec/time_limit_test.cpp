#include <catch2/catch_test_macros.hpp>
#include <catch2/generators/catch_generators.hpp>

#include <cstdint>
#include <optional>
#include <string>

#include "pbrfit/spec/job_spec.hpp"

using pbrfit::spec::parse_slurm_time_limit;

TEST_CASE("Slurm time limits in every accepted form") {
  const auto [written, seconds] = GENERATE(table<std::string, std::int64_t>({
      {"0", 0},
      {"30", 1800},                // minutes
      {"90", 5400},
      {"05:00", 300},              // MM:SS
      {"5:7", 307},
      {"120:00", 7200},
      {"01:00:00", 3600},          // HH:MM:SS
      {"48:00:00", 172800},
      {"1-02:03:04", 93784},       // D-HH:MM:SS
      {"1-2", 93600},              // D-HH
      {"1-02:30", 95400},          // D-HH:MM
      {"14-00:00:00", 1209600},
  }));
  INFO(written);
  CHECK(parse_slurm_time_limit(written) == std::optional<std::int64_t>(seconds));
}

TEST_CASE("malformed Slurm time limits") {
  const std::string written = GENERATE(as<std::string>{}, "", " 30", "30 ", "abc", "1.5", "-1", "+30",
                                       "1:2:3:4", "01:60", "1:75:00", "1:00:60", "1::00", ":30", "30:",
                                       "1-24:00:00", "1-", "-01:00:00", "1-2-3", "1-100", "1-2:3:4:5",
                                       "1234567890", "UNLIMITED", "1-02:03:04x");
  INFO("'" << written << "'");
  CHECK_FALSE(parse_slurm_time_limit(written).has_value());
}
