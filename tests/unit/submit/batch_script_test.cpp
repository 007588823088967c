#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <fstream>
#include <sstream>

#include "pbrfit/core/error.hpp"
#include "pbrfit/submit/batch_script.hpp"

using namespace pbrfit;
using Catch::Matchers::ContainsSubstring;

namespace {

spec::KindCatalogue catalogue() {
  static const spec::Schema lut = [] {
    spec::Schema s("lut");
    s.string("function", "table").require();
    return s;
  }();
  return {{"lut"}, [](const std::string&) -> const spec::Schema& { return lut; }};
}

spec::JobSpec job(const std::string& extra = "") {
  return spec::parse_job_text("name: dfg-a\nkind: lut\noutput: out/r.h5\nresources: {ranks: 3, time_limit: \"02:00:00\"" +
                                  extra + "}\nlut: {function: dfg}\n",
                              "jobs/a.yaml", catalogue());
}

std::string shipped_template() {
  std::ifstream in(std::string(PBRFIT_SOURCE_DIR) + "/cluster/sbatch.template");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("shell quoting survives quotes, spaces and dollar signs") {
  CHECK(submit::shell_quote("plain") == "'plain'");
  CHECK(submit::shell_quote("it's $HOME; rm -rf /") == "'it'\\''s $HOME; rm -rf /'");
}

TEST_CASE("a batch job takes the job's resources, absolute paths and overrides") {
  const auto b = submit::batch_job_for(job(), {}, "/opt/pbrfit", "/home/u/work");
  CHECK(b.ranks == 3);
  CHECK(b.time_limit == "02:00:00");
  CHECK(b.warning_seconds == 600);
  CHECK(b.job_file == "/home/u/work/jobs/a.yaml");
  CHECK(b.output == "/home/u/work/out/r.h5");
  CHECK(b.log == "/home/u/work/out/r.slurm-%j.log");
  CHECK(b.script == "/home/u/work/out/r.h5.sbatch");
  CHECK(b.threads == 1);
  const auto o = submit::batch_job_for(job(), {8, 4, "10:00", "short", "acct"}, "/opt/pbrfit", "/w");
  CHECK(o.ranks == 8);
  CHECK(o.threads == 4);
  CHECK(o.time_limit == "10:00");
  CHECK(o.warning_seconds == 60);
  CHECK(o.partition == "short");
  CHECK(o.account == "acct");
}

TEST_CASE("values that could escape a #SBATCH line are refused") {
  REQUIRE_THROWS_WITH(submit::batch_job_for(job(", partition: \"a b\""), {}, "/p", "/w"),
                      "jobs/a.yaml: error: the partition 'a b' may contain only letters, digits and ._-, to go "
                      "into a Slurm batch script");
  REQUIRE_THROWS_AS(submit::batch_job_for(job(), {0, 0, "", "", "x;reboot"}, "/p", "/w"), InputError);
  REQUIRE_THROWS_AS(submit::batch_job_for(job(), {}, "/p", "/home/my work"), InputError);
  REQUIRE_THROWS_AS(submit::batch_job_for(job(), {0, 0, "soon", "", ""}, "/p", "/w"), InputError);
}

TEST_CASE("refusals quote what they refuse on one line") {
  REQUIRE_THROWS_WITH(submit::batch_job_for(job(), {0, 0, "", "", "a\nb"}, "/p", "/w"),
                      "jobs/a.yaml: error: the account 'a\\nb' may contain only letters, digits and ._- to go "
                      "into a Slurm batch script");
}

TEST_CASE("a zero time limit, which Slurm reads as none, is refused") {
  for (const std::string zero : {"0", "00:00", "0-0", "0:00:00"}) {
    INFO(zero);
    REQUIRE_THROWS_WITH(submit::batch_job_for(job(), {0, 0, zero, "", ""}, "/p", "/w"),
                        "--time: error: '" + zero + "' is zero, which Slurm reads as no limit at all");
  }
}

TEST_CASE("the shipped template renders a requeueable, signalled, resuming script") {
  const auto b = submit::batch_job_for(job(", partition: short, threads: 6"), {}, "/opt/pbrfit", "/w");
  const auto script = submit::render_batch_script(b, shipped_template(), "sbatch.template");
  CHECK_THAT(script, ContainsSubstring("#SBATCH --ntasks=3\n"));
  CHECK_THAT(script, ContainsSubstring("#SBATCH --cpus-per-task=6\n"));
  CHECK_THAT(script, ContainsSubstring("#SBATCH --time=02:00:00\n"));
  CHECK_THAT(script, ContainsSubstring("#SBATCH --partition=short\n"));
  CHECK_THAT(script, ContainsSubstring("# (no account)\n"));
  CHECK_THAT(script, ContainsSubstring("#SBATCH --requeue\n"));
  CHECK_THAT(script, ContainsSubstring("#SBATCH --signal=USR1@600\n"));
  CHECK_THAT(script, ContainsSubstring("srun --mpi=pmix --cpus-per-task=6 '/opt/pbrfit' run '/w/jobs/a.yaml' --output "
                                       "'/w/out/r.h5' --resume"));
  CHECK_THAT(script, !ContainsSubstring("{{"));
}

TEST_CASE("template errors name the template and line") {
  REQUIRE_THROWS_WITH(submit::render_template("a\nb {{nope}}\n", {}, "t.template"),
                      "t.template:2: error: unknown placeholder '{{nope}}' in the batch template");
  REQUIRE_THROWS_WITH(submit::render_template("{{open", {}, "t.template"),
                      "t.template:1: error: unclosed '{{' in the batch template");
  CHECK(submit::render_template("x {{a}} y {{a}}", {{"a", "1"}}, "t") == "x 1 y 1");
}
