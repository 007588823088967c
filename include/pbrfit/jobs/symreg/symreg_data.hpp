#pragma once
// The data of a symbolic-regression job, loaded once per process and shared read-only by its threads: one
// training set per output and a test set (a generator's fresh points, or rows of a file held out by
// test_fraction), with the names of the inputs.
// With cross_inputs (Pesce & Iwanicki 2015, section 5.3) every other output is an extra input of each.
//
// Invariants: at least one output; every dataset passed gp::validate; inputs.size() equals the datasets'
// input count; names are unique within an output's inputs.
#include <memory>
#include <string>
#include <vector>

#include "pbrfit/gp/dataset.hpp"
#include "pbrfit/spec/keys.hpp"

namespace pbrfit::jobs::symreg {

struct SymregOutput {
  std::string name;
  std::vector<std::string> inputs;
  gp::Dataset train;
  gp::Dataset test;  // fresh points of a generator, or the rows test_fraction holds out; may be empty
};

struct SymregData {
  std::vector<SymregOutput> outputs;
  std::string source;  // where the data came from, for the result's attributes
};

// The job's `dataset` section as written: exactly one of `generator`, `csv` or `result` is to be given.
struct DatasetSection {
  spec::Located<std::string> generator, csv, result;
  std::size_t points = 20, test_points = 10'000;
  spec::Located<double> test_fraction;
  std::uint64_t sample_seed = 0;
  spec::Located<std::vector<std::string>> inputs, targets, tables;
  spec::Located<bool> cross_inputs;
};

// Its keys (docs/job-files.md, kind `symreg`, `dataset`).
const spec::Keys<DatasetSection>& dataset_keys();

// The data the section names; `where` is the section's position. Throws InputError at the offending key,
// naming the data file and, for CSV, the line and column of a bad value.
std::shared_ptr<const SymregData> load_symreg_data(const DatasetSection& dataset, const SourcePosition& where);

}  // namespace pbrfit::jobs::symreg
