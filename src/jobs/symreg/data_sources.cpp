// Where symbolic regression reads its data (symreg_data.hpp): a built-in generator, a CSV file, or tables of
// a pbrfit result (their axes are the inputs).
#include <cmath>
#include <set>

#include "pbrfit/core/error.hpp"
#include "pbrfit/gp/benchmark_problems.hpp"
#include "pbrfit/jobs/read_at_key.hpp"
#include "pbrfit/jobs/symreg/csv_table.hpp"
#include "pbrfit/jobs/symreg/result_table_source.hpp"
#include "pbrfit/jobs/symreg/symreg_data.hpp"
#include "pbrfit/store/atomic_file.hpp"
#include "pbrfit/store/result_file.hpp"

namespace pbrfit::jobs::symreg {
namespace {

constexpr std::uint64_t max_csv_bytes = std::uint64_t(256) << 20;

std::vector<std::string> generator_names() {
  std::vector<std::string> names;
  for (const auto& p : gp::benchmark_problems()) names.push_back(p.name);
  return names;
}

SymregData from_generator(const spec::Section& s) {
  const auto* problem = gp::find_benchmark_problem(s.get_string("generator"));
  const std::size_t points = std::size_t(s.get_int("points")), test = std::size_t(s.get_int("test_points"));
  const RandomStream stream(std::uint64_t(s.get_int("sample_seed")), 0, 0);
  SymregOutput out{"y", {"x"}, gp::sample(*problem, points, stream.derive(0)), gp::sample(*problem, test, stream.derive(1))};
  return {{out}, "generator " + problem->name + ": y = " + problem->formula + ", x uniform in [" +
                     std::to_string(problem->lower) + ", " + std::to_string(problem->upper) + "]"};
}

SymregData from_csv(const spec::Section& s) {
  const std::string& path = s.get_string("csv");
  const Bytes bytes = read_at_key(s, "csv", path, [&] { return store::read_whole_file(path, max_csv_bytes); });
  const CsvTable table = parse_csv({reinterpret_cast<const char*>(bytes.data()), bytes.size()}, path);
  if (!s.given("inputs") || !s.given("targets")) s.reject("csv", "needs 'inputs' and 'targets': the columns to use");
  std::vector<std::vector<double>> inputs;
  for (const auto& name : s.get_string_list("inputs")) inputs.push_back(table.column(name, s.position("inputs")));
  SymregData data{{}, "CSV file " + path};
  for (const auto& target : s.get_string_list("targets"))
    data.outputs.push_back(output_from_columns(target, s.get_string_list("inputs"), inputs,
                                               table.column(target, s.position("targets"))));
  return data;
}

SymregData from_result(const spec::Section& s) {
  const std::string& path = s.get_string("result");
  const auto summary = read_at_key(s, "result", path, [&] { return store::read_result_summary(path); });
  if (summary.state != store::RunStatus::complete)
    s.reject("result", "names " + path + ", whose job is " + store::run_status_name(summary.state) + ", not complete");
  if (!s.given("tables")) s.reject("result", "needs 'tables': the tables to regress, e.g. [dfg/scale]");
  SymregData data{{}, "pbrfit result " + path + " (job " + summary.job_name + ")"};
  for (const auto& table : s.get_string_list("tables")) {
    try {
      data.outputs.push_back(output_from_result_table(path, table));
    } catch (const RunError& e) {
      s.reject("tables", "names '" + table + "', which " + path + " cannot give: " + e.what());
    }
  }
  return data;
}

// With cross_inputs every output also reads the others' targets (all outputs share the rows).
void add_cross_inputs(const spec::Section& s, SymregData& data) {
  if (data.outputs.size() < 2) s.reject("cross_inputs", "needs at least two outputs");
  const auto rows = data.outputs[0].train.rows();
  for (const auto& o : data.outputs)
    if (o.train.rows() != rows) s.reject("cross_inputs", "needs outputs with the same rows (values missing differ)");
  const auto original = data.outputs;
  for (std::size_t k = 0; k < data.outputs.size(); ++k) {
    auto& out = data.outputs[k];
    for (std::size_t j = 0; j < original.size(); ++j) {
      if (j == k) continue;
      out.inputs.push_back(original[j].name);
      out.train.inputs.conservativeResize(Eigen::NoChange, out.train.inputs.cols() + 1);
      out.train.inputs.col(out.train.inputs.cols() - 1) = original[j].train.target;
    }
  }
}

}  // namespace

std::shared_ptr<const SymregData> load_symreg_data(const spec::Section& s) {
  const int sources = int(s.given("generator")) + int(s.given("csv")) + int(s.given("result"));
  if (sources != 1) throw InputError(s.position(), "'dataset' needs exactly one of generator, csv or result");
  SymregData data = s.given("generator") ? from_generator(s) : s.given("csv") ? from_csv(s) : from_result(s);
  std::set<std::string> names;
  for (const auto& o : data.outputs)
    if (!names.insert(o.name).second) s.reject(s.given("csv") ? "targets" : "tables", "names '" + o.name + "' twice");
  if (s.get_bool("cross_inputs")) add_cross_inputs(s, data);
  for (const auto& o : data.outputs) {
    if (o.train.rows() < 2) s.reject(s.given("csv") ? "csv" : "result", "gives output '" + o.name + "' fewer than 2 rows");
    gp::validate(o.train);
  }
  return std::make_shared<const SymregData>(std::move(data));
}

spec::Schema dataset_schema() {
  spec::Schema s("dataset");
  s.choice("generator", generator_names(), "a built-in benchmark problem (Nguyen-1..8: nguyen1 ... nguyen8)");
  s.integer("points", "generator: training points, uniform on the problem's range").range(2, 10'000'000).defaults_to(std::int64_t{20});
  s.integer("test_points", "generator: fresh points the front is also judged on").range(0, 10'000'000).defaults_to(std::int64_t{10'000});
  s.integer("sample_seed", "generator: the seed of the points (the job's seed drives the search)").at_least(0).defaults_to(std::int64_t{0});
  s.string("csv", "a CSV file with a header line of column names");
  s.string_list("inputs", 1, 64, "csv: the columns that are inputs");
  s.string_list("targets", 1, 16, "csv: the columns to regress, one output each");
  s.string("result", "a complete pbrfit result file");
  s.string_list("tables", 1, 16, "result: tables to regress (GROUP/TABLE), one output each; their axes are the inputs");
  s.boolean("cross_inputs", "with several outputs, each may read the others (Pesce & Iwanicki 2015, section 5.3)").defaults_to(false);
  return s;
}

}  // namespace pbrfit::jobs::symreg
