// Where symbolic regression reads its data (symreg_data.hpp): a built-in generator, a CSV file, or tables of
// a pbrfit result (their axes are the inputs).
#include <algorithm>
#include <cmath>
#include <set>

#include "pbrfit/core/error.hpp"
#include "pbrfit/core/random_stream.hpp"
#include "pbrfit/gp/benchmark_problems.hpp"
#include "pbrfit/jobs/read_named_file.hpp"
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

SymregData from_generator(const DatasetSection& s) {
  const auto* problem = gp::find_benchmark_problem(s.generator.value);
  const RandomStream stream(s.sample_seed, 0, 0);
  SymregOutput out{"y", {"x"}, gp::sample(*problem, s.points, stream.derive(0)),
                   gp::sample(*problem, s.test_points, stream.derive(1))};
  return {{out}, "generator " + problem->name + ": y = " + problem->formula + ", x uniform in [" +
                     std::to_string(problem->lower) + ", " + std::to_string(problem->upper) + "]"};
}

SymregData from_csv(const DatasetSection& s) {
  const std::string& path = s.csv.value;
  Bytes bytes;
  if (const auto problem = read_named_file(path, [&] { bytes = store::read_whole_file(path, max_csv_bytes); });
      !problem.empty())
    s.csv.reject(problem);
  const CsvTable table = parse_csv({reinterpret_cast<const char*>(bytes.data()), bytes.size()}, path);
  if (!s.inputs.written || !s.targets.written) s.csv.reject("needs 'inputs' and 'targets': the columns to use");
  std::vector<std::vector<double>> inputs;
  for (const auto& name : s.inputs.value) inputs.push_back(table.column(name, s.inputs.where));
  SymregData data{{}, "CSV file " + path};
  for (const auto& target : s.targets.value)
    data.outputs.push_back(output_from_columns(target, s.inputs.value, inputs, table.column(target, s.targets.where)));
  return data;
}

SymregData from_result(const DatasetSection& s) {
  const std::string& path = s.result.value;
  store::ResultSummary summary;
  if (const auto problem = read_named_file(path, [&] { summary = store::read_result_summary(path); }); !problem.empty())
    s.result.reject(problem);
  if (summary.state != store::RunStatus::complete)
    s.result.reject("names " + path + ", whose job is " + store::run_status_name(summary.state) + ", not complete");
  if (!s.tables.written) s.result.reject("needs 'tables': the tables to regress, e.g. [dfg/scale]");
  SymregData data{{}, "pbrfit result " + path + " (job " + summary.job_name + ")"};
  for (const auto& table : s.tables.value) {
    try {
      data.outputs.push_back(output_from_result_table(path, table));
    } catch (const RunError& e) {
      s.tables.reject("names '" + table + "', which " + path + " cannot give: " + e.what());
    }
  }
  return data;
}

// With cross_inputs every output also reads the others' targets (all outputs share the rows).
void add_cross_inputs(const DatasetSection& s, SymregData& data) {
  if (data.outputs.size() < 2) s.cross_inputs.reject("needs at least two outputs");
  const auto rows = data.outputs[0].train.rows();
  for (const auto& o : data.outputs)
    if (o.train.rows() != rows) s.cross_inputs.reject("needs outputs with the same rows (values missing differ)");
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

// Rows of `all` in `order` from `first` on.
gp::Dataset rows_of(const gp::Dataset& all, const std::vector<Eigen::Index>& order, std::size_t first, std::size_t count) {
  gp::Dataset part;
  part.inputs.resize(static_cast<Eigen::Index>(count), all.inputs.cols());
  part.target.resize(static_cast<Eigen::Index>(count));
  for (std::size_t i = 0; i < count; ++i) {
    const Eigen::Index row = order[first + i];
    part.inputs.row(static_cast<Eigen::Index>(i)) = all.inputs.row(row);
    part.target[static_cast<Eigen::Index>(i)] = all.target[row];
  }
  return part;
}

// test_fraction: round(fraction x rows) rows of each output held out, chosen by a shuffle seeded by
// sample_seed (outputs of as many rows hold out the same rows); both parts keep the file's row order.
void hold_out_rows(const DatasetSection& s, SymregData& data) {
  for (auto& out : data.outputs) {
    const auto rows = static_cast<std::size_t>(out.train.rows());
    const auto held = static_cast<std::size_t>(std::llround(s.test_fraction.value * double(rows)));
    if (held == 0) continue;
    if (rows - held < 2)
      s.test_fraction.reject("leaves output '" + out.name + "' fewer than 2 training rows (of " + std::to_string(rows) + ")");
    std::vector<Eigen::Index> order(rows);
    for (std::size_t i = 0; i < rows; ++i) order[i] = static_cast<Eigen::Index>(i);
    RandomStream random(s.sample_seed, 0, 2);
    for (std::size_t i = rows - 1; i > 0; --i) std::swap(order[i], order[random.below(i + 1)]);
    std::sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(held));
    std::sort(order.begin() + static_cast<std::ptrdiff_t>(held), order.end());
    out.test = rows_of(out.train, order, 0, held);
    out.train = rows_of(out.train, order, held, rows - held);
  }
}

spec::Keys<DatasetSection> make_dataset_keys() {
  using S = DatasetSection;
  using std::int64_t;
  spec::Keys<S> k("dataset");
  k.choice("generator", generator_names(), "a built-in benchmark problem (Nguyen-1..8: nguyen1 ... nguyen8)",
           &S::generator);
  k.integer("points", "generator: training points, uniform on the problem's range", &S::points)
      .range(2, 1'000'000)
      .defaults_to(int64_t{20});
  k.integer("test_points", "generator: fresh points the front is also judged on", &S::test_points)
      .range(0, 1'000'000)
      .defaults_to(int64_t{10'000});
  k.number("test_fraction", "csv, result: the share of rows held out (chosen by sample_seed), on which every front member is also judged",
           &S::test_fraction)
      .range(0.0, 0.9)
      .defaults_to(0.0);
  k.integer("sample_seed", "generator: the seed of the points; test_fraction: of the rows held out (the job's seed drives the search)",
            &S::sample_seed)
      .at_least(0)
      .defaults_to(int64_t{0});
  k.string("csv", "a CSV file with a header line of column names", &S::csv);
  k.string_list("inputs", 1, 64, "csv: the columns that are inputs", &S::inputs);
  k.string_list("targets", 1, 16, "csv: the columns to regress, one output each", &S::targets);
  k.string("result", "a complete pbrfit result file", &S::result);
  k.string_list("tables", 1, 16, "result: tables to regress (GROUP/TABLE), one output each; their axes are the inputs",
                &S::tables);
  k.boolean("cross_inputs", "with several outputs, each may read the others (Pesce & Iwanicki 2015, section 5.3)",
            &S::cross_inputs)
      .defaults_to(false);
  return k;
}

}  // namespace

const spec::Keys<DatasetSection>& dataset_keys() {
  static const spec::Keys<DatasetSection> keys = make_dataset_keys();
  return keys;
}

std::shared_ptr<const SymregData> load_symreg_data(const DatasetSection& s, const SourcePosition& where) {
  const int sources = int(s.generator.written) + int(s.csv.written) + int(s.result.written);
  if (sources != 1) throw InputError(where, "'dataset' needs exactly one of generator, csv or result");
  SymregData data = s.generator.written ? from_generator(s) : s.csv.written ? from_csv(s) : from_result(s);
  std::set<std::string> names;
  for (const auto& o : data.outputs)
    if (!names.insert(o.name).second) (s.csv.written ? s.targets : s.tables).reject("names '" + o.name + "' twice");
  if (s.cross_inputs.value) add_cross_inputs(s, data);
  if (s.test_fraction.written && s.generator.written)
    s.test_fraction.reject("is for csv and result data; a generator draws fresh test points (test_points)");
  hold_out_rows(s, data);
  for (const auto& o : data.outputs) {
    if (o.train.rows() < 2) (s.csv.written ? s.csv : s.result).reject("gives output '" + o.name + "' fewer than 2 rows");
    gp::validate(o.train);
  }
  return std::make_shared<const SymregData>(std::move(data));
}

}  // namespace pbrfit::jobs::symreg
