#pragma once
// A validated `symreg` job: the data, each island's evolution settings, the island model (islands per
// output on a ring, epochs of migration_interval generations) and the reference expressions (anchors) the
// front is compared with.
//
// Invariants (symreg_kind.cpp establishes them): islands >= 1; migration_interval >= 1; generations >= 1;
// migrants < the population size; every anchor names an output of the data and parses for its inputs.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "pbrfit/gp/evolve.hpp"
#include "pbrfit/gp/program.hpp"
#include "pbrfit/jobs/symreg/symreg_data.hpp"

namespace pbrfit::jobs::symreg {

struct Anchor {
  std::string name;
  std::size_t output = 0;
  std::string text;
  gp::Program program;
};

struct SymregSettings {
  std::shared_ptr<const SymregData> data;
  gp::EvolveOptions evolve;  // shape.input_count is set per output
  std::size_t islands = 4;
  std::size_t generations = 100;
  std::size_t migration_interval = 10;
  std::size_t migrants = 5;
  std::size_t max_evaluations = 0;  // over the whole run; 0: no limit but the generations
  std::vector<Anchor> anchors;

  std::size_t epochs() const { return (generations + migration_interval - 1) / migration_interval; }
};

}  // namespace pbrfit::jobs::symreg
