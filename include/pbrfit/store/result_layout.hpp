#pragma once
// The shape of a job's result file, declared by the job kind before any work runs: groups of tables
// over named axes. Every table is float64; every axis is a 1-D dataset in the same group, attached to
// the table's dimensions as an HDF5 dimension scale, so a reader needs nothing from pbrfit.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace pbrfit::store {

struct Axis {
  std::string name;            // dataset name inside the group, e.g. "n_dot_v"
  std::vector<double> values;  // sample positions
  std::string description;     // what the values mean, including the parametrization
};

struct Table {
  std::string name;                 // dataset name inside the group, e.g. "scale"
  std::vector<std::string> axes;    // axis names, outermost first; the first axis grows as rows arrive
  std::string description;
};

struct Group {
  std::string name;                                // e.g. "dfg"
  std::string description;
  std::map<std::string, std::string> attributes;   // settings a reader needs (parametrization, ...)
  std::vector<Axis> axes;
  std::vector<Table> tables;

  const Axis& axis(const std::string& axis_name) const;
};

struct ResultLayout {
  std::vector<Group> groups;
};

// A rectangular block of one table's values, row-major over the table's axes.
struct Block {
  std::string group;
  std::string table;
  std::vector<std::uint64_t> offset;  // per axis
  std::vector<std::uint64_t> count;   // per axis
  std::vector<double> values;         // product(count) values
};

}  // namespace pbrfit::store
