// Every way a job file can be rejected, with the exact one-line message users see.
#include <catch2/catch_test_macros.hpp>
#include <catch2/generators/catch_generators.hpp>
#include <catch2/generators/catch_generators_range.hpp>

#include <string>
#include <vector>

#include "pbrfit/core/error.hpp"
#include "pbrfit/spec/job_spec.hpp"
#include "test_kinds.hpp"

namespace {

using pbrfit::InputError;
using pbrfit::spec::parse_job_text;
using pbrfit::spec::testing::test_kinds;

struct BadJob {
  std::string what;
  std::string text;
  std::string message;  // the complete what() of the InputError
};

const std::string long_name(101, 'a');

// Ten lists of ten aliases of the previous list: 10^10 values once expanded.
std::string billion_laughs() {
  std::string text = "name: dfg\nkind: lut\nlut: {function: dfg}\nl0: &l0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int level = 1; level <= 10; ++level) {
    const std::string name = std::to_string(level);
    const std::string previous = std::string("*l").append(std::to_string(level - 1));
    text += "l" + name + ": &l" + name + " [" + previous;
    for (int i = 1; i < 10; ++i) text += ", " + previous;
    text += "]\n";
  }
  return text;
}

const std::vector<BadJob> bad_jobs = {
    // The document as a whole.
    {"invalid YAML", R"(name: dfg
kind: [lut
)",
     "test.yaml:3:1: error: invalid YAML: end of sequence flow not found"},
    {"top level is a list", R"(- name: dfg
- kind: lut
)",
     "test.yaml:1:1: error: a job file must be a mapping of keys to values"},
    {"top level is a scalar", "dfg\n",
     "test.yaml:1:1: error: a job file must be a mapping of keys to values"},
    {"two documents", R"(name: dfg
kind: lut
---
name: other
)",
     "test.yaml:4:1: error: a job file must hold a single YAML document"},
    {"an alias inside what it refers to", R"(name: dfg
kind: lut
lut: &x {function: dfg, n_dot_v: *x}
)",
     "test.yaml:3:25: error: the value of 'lut.n_dot_v' is an alias of a mapping or list that contains it"},
    {"a list holding itself", R"(name: dfg
kind: lut
lut: {function: dfg}
loop: &y [1, *y]
)",
     "test.yaml:4:1: error: the value of 'loop[1]' is an alias of a mapping or list that contains it"},
    {"aliases expanding beyond the file", billion_laughs(),
     "test.yaml:7:1: error: aliases expand the job file to too many values"},
    {"a key that is not a name", R"(name: dfg
kind: lut
[a, b]: 1
lut: {function: dfg}
)",
     "test.yaml:3:1: error: a key in 'job' must be a name, got a list"},

    // kind and the kind's section.
    {"kind missing", R"(name: dfg
lut: {function: dfg}
)",
     "test.yaml:1:1: error: missing required key 'kind' in 'job'"},
    {"kind misspelt", R"(name: dfg
kind: lutt
)",
     "test.yaml:2:7: error: 'kind' must be one of lut, sweep; got 'lutt'; did you mean 'lut'?"},
    {"kind unknown", R"(name: dfg
kind: spectral
)",
     "test.yaml:2:7: error: 'kind' must be one of lut, sweep; got 'spectral'"},
    {"kind is a mapping", R"(name: dfg
kind: {name: lut}
)",
     "test.yaml:2:7: error: 'kind' must be one of lut, sweep; got a mapping"},
    {"kind section missing", R"(name: dfg
kind: lut
seed: 3
)",
     "test.yaml:2:7: error: missing required section 'lut' for kind 'lut'"},
    {"section of another kind", R"(name: dfg
kind: lut
sweep: {steps: 3}
lut: {function: dfg}
)",
     "test.yaml:3:1: error: section 'sweep' does not belong to a job of kind 'lut'"},
    {"kind section blank", R"(name: dfg
kind: lut
lut:
)",
     "test.yaml:3:1: error: 'lut' must be a mapping, got an empty value"},
    {"kind section is a list", R"(name: dfg
kind: lut
lut: [dfg]
)",
     "test.yaml:3:6: error: 'lut' must be a mapping, got a list"},

    // Top-level keys.
    {"name missing", R"(kind: lut
lut: {function: dfg}
)",
     "test.yaml:1:1: error: missing required key 'name' in 'job'"},
    {"unknown key, close to a valid one", R"(name: dfg
kind: lut
sed: 4
lut: {function: dfg}
)",
     "test.yaml:3:1: error: unknown key 'sed' in 'job'; did you mean 'seed'?"},
    {"unknown key, far from all", R"(name: dfg
kind: lut
priority: high
lut: {function: dfg}
)",
     "test.yaml:3:1: error: unknown key 'priority' in 'job'; "
     "valid keys: name, kind, seed, output, checkpoint, resources, lut"},
    {"duplicate key", R"(name: dfg
seed: 1
kind: lut
seed: 2
lut: {function: dfg}
)",
     "test.yaml:4:1: error: duplicate key 'seed' in 'job'"},
    {"seed not a number", R"(name: dfg
kind: lut
seed: abc
lut: {function: dfg}
)",
     "test.yaml:3:7: error: 'seed' must be an integer, got 'abc'"},
    {"seed with a fraction", R"(name: dfg
kind: lut
seed: 10.5
lut: {function: dfg}
)",
     "test.yaml:3:7: error: 'seed' must be an integer, got '10.5'"},
    {"seed negative", R"(name: dfg
kind: lut
seed: -1
lut: {function: dfg}
)",
     "test.yaml:3:7: error: 'seed' must be at least 0, got -1"},
    {"seed blank", R"(name: dfg
kind: lut
seed:
lut: {function: dfg}
)",
     "test.yaml:3:1: error: 'seed' must be an integer, got an empty value"},
    {"seed null", R"(name: dfg
kind: lut
seed: ~
lut: {function: dfg}
)",
     "test.yaml:3:7: error: 'seed' must be an integer, got '~'"},
    {"seed beyond 64 bits", R"(name: dfg
kind: lut
seed: 99999999999999999999
lut: {function: dfg}
)",
     "test.yaml:3:7: error: 'seed' must be an integer that fits in 64 bits, got 99999999999999999999"},
    {"name with a space", R"(name: my job
kind: lut
lut: {function: dfg}
)",
     "test.yaml:1:7: error: 'name' may contain only letters, digits, '.', '_' and '-', got 'my job'"},
    {"name too long", "name: " + long_name + "\nkind: lut\nlut: {function: dfg}\n",
     "test.yaml:1:7: error: 'name' must be at most 100 characters long, got 101"},
    {"name empty", R"(name: ""
kind: lut
lut: {function: dfg}
)",
     "test.yaml:1:7: error: 'name' must not be empty"},
    {"name blank", R"(name:
kind: lut
lut: {function: dfg}
)",
     "test.yaml:1:1: error: 'name' must be a string, got an empty value"},
    {"output without .h5", R"(name: dfg
kind: lut
output: results/x.hdf5
lut: {function: dfg}
)",
     "test.yaml:3:9: error: 'output' must end in .h5, got 'results/x.hdf5'"},
    {"output empty", R"(name: dfg
kind: lut
output: ''
lut: {function: dfg}
)",
     "test.yaml:3:9: error: 'output' must not be empty"},

    // checkpoint and resources.
    {"checkpoint not a mapping", R"(name: dfg
kind: lut
checkpoint: 10
lut: {function: dfg}
)",
     "test.yaml:3:13: error: 'checkpoint' must be a mapping, got '10'"},
    {"checkpoint interval not a number", R"(name: dfg
kind: lut
checkpoint:
  interval_seconds: soon
lut: {function: dfg}
)",
     "test.yaml:4:21: error: 'interval_seconds' must be a number, got 'soon'"},
    {"checkpoint items negative", R"(name: dfg
kind: lut
checkpoint: {interval_items: -5}
lut: {function: dfg}
)",
     "test.yaml:3:30: error: 'interval_items' must be at least 0, got -5"},
    {"checkpoint key misspelt", R"(name: dfg
kind: lut
checkpoint:
  interval_second: 10
lut: {function: dfg}
)",
     "test.yaml:4:3: error: unknown key 'interval_second' in 'checkpoint'; did you mean 'interval_seconds'?"},
    {"ranks zero", R"(name: dfg
kind: lut
resources:
  ranks: 0
lut: {function: dfg}
)",
     "test.yaml:4:10: error: 'ranks' must be between 1 and 65536, got 0"},
    {"ranks a list", R"(name: dfg
kind: lut
resources: {ranks: [1, 2]}
lut: {function: dfg}
)",
     "test.yaml:3:20: error: 'ranks' must be an integer, got a list"},
    {"time limit malformed", R"(name: dfg
kind: lut
resources:
  time_limit: 1:75:00
lut: {function: dfg}
)",
     "test.yaml:4:15: error: 'time_limit' must be a Slurm time limit "
     "(MM, MM:SS, HH:MM:SS, D-HH, D-HH:MM or D-HH:MM:SS), got '1:75:00'"},
    {"time limit zero", R"(name: dfg
kind: lut
resources:
  time_limit: 0
lut: {function: dfg}
)",
     "test.yaml:4:15: error: 'time_limit' must be longer than zero, got '0'"},
    {"partition a mapping", R"(name: dfg
kind: lut
resources:
  partition: {name: gpu}
lut: {function: dfg}
)",
     "test.yaml:4:14: error: 'partition' must be a string, got a mapping"},
    {"resources key unknown", R"(name: dfg
kind: lut
resources:
  nodes: 4
lut: {function: dfg}
)",
     "test.yaml:4:3: error: unknown key 'nodes' in 'resources'; "
     "valid keys: ranks, threads, time_limit, partition, account"},

    // The kind's section (the test schema in test_kinds.hpp).
    {"required key missing", R"(name: dfg
kind: lut
lut:
  tolerance: 0.1
)",
     "test.yaml:4:3: error: missing required key 'function' in 'lut'"},
    {"key misspelt", R"(name: dfg
kind: lut
lut:
  function: dfg
  tolerence: 1e-3
)",
     "test.yaml:5:3: error: unknown key 'tolerence' in 'lut'; did you mean 'tolerance'?"},
    {"key unknown", R"(name: dfg
kind: lut
lut:
  function: dfg
  colour: red
)",
     "test.yaml:5:3: error: unknown key 'colour' in 'lut'; valid keys: function, resolution, moments, "
     "tolerance, max_evaluations, importance_sampling, visibility, label, n_dot_v, roughness"},
    {"duplicate key in the section", R"(name: dfg
kind: lut
lut:
  function: dfg
  tolerance: 0.1
  function: directional_albedo
)",
     "test.yaml:6:3: error: duplicate key 'function' in 'lut'"},
    {"number at an exclusive bound", R"(name: dfg
kind: lut
lut:
  function: dfg
  tolerance: 0
)",
     "test.yaml:5:14: error: 'tolerance' must be greater than 0, got 0"},
    {"number echoed as written", R"(name: dfg
kind: lut
lut:
  function: dfg
  tolerance: -1e-6
)",
     "test.yaml:5:14: error: 'tolerance' must be greater than 0, got -1e-6"},
    {"number that is a word", R"(name: dfg
kind: lut
lut:
  function: dfg
  tolerance: tight
)",
     "test.yaml:5:14: error: 'tolerance' must be a number, got 'tight'"},
    {"integer written in exponent form", R"(name: dfg
kind: lut
lut:
  function: dfg
  max_evaluations: 1e9
)",
     "test.yaml:5:20: error: 'max_evaluations' must be an integer, got '1e9'"},
    {"integer above its range", R"(name: dfg
kind: lut
lut:
  function: dfg
  max_evaluations: 2000000000
)",
     "test.yaml:5:20: error: 'max_evaluations' must be between 1 and 1000000000, got 2000000000"},
    {"boolean", R"(name: dfg
kind: lut
lut:
  function: dfg
  importance_sampling: maybe
)",
     "test.yaml:5:24: error: 'importance_sampling' must be true or false, got 'maybe'"},
    {"choice misspelt", R"(name: dfg
kind: lut
lut:
  function: dfg
  visibility: seperable
)",
     "test.yaml:5:15: error: 'visibility' must be one of height_correlated, separable, separable_schlick; "
     "got 'seperable'; did you mean 'separable'?"},
    {"choice unknown", R"(name: dfg
kind: lut
lut:
  function: dfg
  visibility: smith
)",
     "test.yaml:5:15: error: 'visibility' must be one of height_correlated, separable, separable_schlick; "
     "got 'smith'"},
    {"choice given a list", R"(name: dfg
kind: lut
lut:
  function: [dfg]
)",
     "test.yaml:4:13: error: 'function' must be one of dfg, directional_albedo, specular_occlusion; "
     "got a list"},
    {"string given a mapping", R"(name: dfg
kind: lut
lut:
  function: dfg
  label: {text: x}
)",
     "test.yaml:5:10: error: 'label' must be a string, got a mapping"},
    {"integer list given a scalar", R"(name: dfg
kind: lut
lut:
  function: dfg
  resolution: 64
)",
     "test.yaml:5:15: error: 'resolution' must be a list of 2 integers, got '64'"},
    {"integer list too long", R"(name: dfg
kind: lut
lut:
  function: dfg
  resolution: [64, 64, 64]
)",
     "test.yaml:5:15: error: 'resolution' must be a list of 2 integers, got a list of 3 items"},
    {"integer list item not an integer", R"(name: dfg
kind: lut
lut:
  function: dfg
  resolution: [64, 6.4]
)",
     "test.yaml:5:20: error: 'resolution' item 2 must be an integer, got '6.4'"},
    {"integer list item out of range", R"(name: dfg
kind: lut
lut:
  function: dfg
  resolution: [0, 64]
)",
     "test.yaml:5:16: error: 'resolution' item 1 must be between 1 and 4096, got 0"},
    {"integer list empty", R"(name: dfg
kind: lut
lut:
  function: dfg
  moments: []
)",
     "test.yaml:5:12: error: 'moments' must be a list of 1 to 3 integers, got an empty list"},
    {"nested section missing a required key", R"(name: dfg
kind: lut
lut:
  function: dfg
  n_dot_v:
    min: 0.2
)",
     "test.yaml:6:5: error: missing required key 'samples' in 'lut.n_dot_v'"},
    {"nested section value out of range", R"(name: dfg
kind: lut
lut:
  function: dfg
  n_dot_v: {samples: 8, max: 1.5}
)",
     "test.yaml:5:30: error: 'max' must be between 0 and 1, got 1.5"},
    {"nested section key misspelt", R"(name: dfg
kind: lut
lut:
  function: dfg
  n_dot_v:
    sample: 8
)",
     "test.yaml:6:5: error: unknown key 'sample' in 'lut.n_dot_v'; did you mean 'samples'?"},
    {"nested section duplicate key", R"(name: dfg
kind: lut
lut:
  function: dfg
  roughness: {min: 0.1, min: 0.2}
)",
     "test.yaml:5:25: error: duplicate key 'min' in 'lut.roughness'"},
};

}  // namespace

TEST_CASE("each bad job file is rejected with its exact message") {
  const BadJob& bad = GENERATE(from_range(bad_jobs));
  INFO("case: " << bad.what << "\n" << bad.text);
  try {
    (void)parse_job_text(bad.text, "test.yaml", test_kinds());
    FAIL("accepted");
  } catch (const InputError& error) {
    CHECK(std::string(error.what()) == bad.message);
  }
}

TEST_CASE("a rejection's position and message are also available separately") {
  try {
    (void)parse_job_text("name: dfg\nkind: lut\nseed: abc\nlut: {function: dfg}\n", "x.yaml", test_kinds());
    FAIL("accepted");
  } catch (const InputError& error) {
    CHECK(error.where().file == "x.yaml");
    CHECK(error.where().line == 3);
    CHECK(error.where().column == 7);
    CHECK(error.message() == "'seed' must be an integer, got 'abc'");
  }
}

TEST_CASE("messages stay on one line whatever the user wrote") {
  try {
    const std::string text = "name: dfg\nkind: lut\nseed: \"a\\nb\"\nlut: {function: dfg}\n";
    (void)parse_job_text(text, "t.yaml", test_kinds());
    FAIL("accepted");
  } catch (const InputError& error) {
    CHECK(std::string(error.what()) == "t.yaml:3:7: error: 'seed' must be an integer, got 'a\\nb'");
  }
}

TEST_CASE("an unclosed quote is reported where it opens, not as missing keys") {
  for (const std::string value : {"\"results/x.h5", "'results/x.h5", "\"a\\\"", "'it''s"}) {
    INFO(value);
    try {
      (void)parse_job_text("name: dfg\noutput: " + value + "\nkind: lut\nlut: {function: dfg}\n", "t.yaml",
                           test_kinds());
      FAIL("accepted");
    } catch (const InputError& error) {
      CHECK(std::string(error.what()) == std::string("t.yaml:2:9: error: unclosed quote: the value starting with ") +
                                             value[0] + " must end with " + value[0] + " on the same line");
    }
  }
}

TEST_CASE("a 5000-digit number is shortened in its message") {
  try {
    (void)parse_job_text("name: dfg\nkind: lut\nseed: " + std::string(5000, '9') + "\nlut: {function: dfg}\n",
                         "t.yaml", test_kinds());
    FAIL("accepted");
  } catch (const InputError& error) {
    const std::string message = error.what();
    CHECK(message.size() < 200);
    CHECK(message.find('\n') == std::string::npos);
    CHECK(message.rfind("t.yaml:3:7: error: 'seed' ", 0) == 0);
  }
}

TEST_CASE("long values are shortened in messages") {
  const std::string word(70, 'w');
  try {
    (void)parse_job_text("name: dfg\nkind: lut\nseed: " + word + "\nlut: {function: dfg}\n", "t.yaml",
                         test_kinds());
    FAIL("accepted");
  } catch (const InputError& error) {
    CHECK(std::string(error.what()) ==
          "t.yaml:3:7: error: 'seed' must be an integer, got '" + std::string(60, 'w') + "...'");
  }
}
