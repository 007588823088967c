#pragma once
// The shape of a job's result file, declared by the job kind before any work runs: groups of tables
// over named axes. Every axis is a 1-D float64 dataset in its group, attached to the tables' dimensions
// as an HDF5 dimension scale, so a reader needs nothing from pbrfit.
//
// A table holds elements of one value type (numbers or texts), or records of named fields. A fixed
// table spans its axes and fills in as blocks arrive (unwritten numbers read as NaN for floats, 0 for
// integers). A growing table has no axis along its first dimension: each finished work item appends
// rows, in work-item order, so the rows are the same whatever the rank count or interruptions.
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pbrfit/store/number.hpp"

namespace pbrfit::store {

enum class ValueType : std::uint8_t { f32, f64, i32, i64, u8, u32, u64, text };

bool is_numeric(ValueType type);
bool is_integer(ValueType type);
bool is_signed_integer(ValueType type);  // i32, i64
const char* type_name(ValueType type);
// Whether an element of `type` holds `number` exactly: a real type any number, an integer type an integer
// within its range.
bool holds(ValueType type, const Number& number);

struct Axis {
  std::string name;            // dataset name inside the group, e.g. "n_dot_v"
  std::vector<double> values;  // sample positions
  std::string description = {};  // what the values mean, including the parametrization
};

// One member of a record.
struct Field {
  std::string name;
  ValueType type = ValueType::f64;
  std::string description;
};

struct Table {
  std::string name;               // dataset name inside the group, e.g. "scale"
  std::vector<std::string> axes;  // dimension names, outermost first; for a growing table the first is a
                                  // label only (e.g. "member"), the others are axes of the group
  std::string description;
  ValueType type = ValueType::f64;        // element type when `fields` is empty
  std::vector<Field> fields = {};         // non-empty: every element is a record of these fields
  bool growing = false;                   // rows are appended along the first dimension
  std::vector<std::uint64_t> chunk = {};  // chunk shape per dimension; empty: chosen by the store
  // Further string attributes of the dataset for readers (docs/report.md: `role`, `anchor`, ...).
  std::map<std::string, std::string> attributes = {};

  bool is_record() const { return !fields.empty(); }
  // Numeric and text values per element: 1 and 0 for numbers, 0 and 1 for texts, the field counts for
  // records. A block holds elements x these many values of each kind.
  std::size_t numbers_per_element() const;
  std::size_t texts_per_element() const;
};

struct Group {
  std::string name;                                // e.g. "dfg"; "ltc/level2" nests (parents are created)
  std::string description;
  std::map<std::string, std::string> attributes;   // settings a reader needs (parametrization, ...)
  std::vector<Axis> axes;
  std::vector<Table> tables;

  const Axis& axis(const std::string& axis_name) const;
};

struct ResultLayout {
  std::vector<Group> groups;
};

// A rectangular block of one table, row-major over the table's dimensions. Numbers (numeric elements,
// or the numeric fields of each record in field order) go to `values`, integers as integers (number.hpp),
// texts to `texts`. For a growing
// table offset[0] counts rows within what one work item appends; the runtime moves it to the row where
// the item's rows start.
struct Block {
  std::string group;
  std::string table;
  std::vector<std::uint64_t> offset;  // per dimension
  std::vector<std::uint64_t> count;   // per dimension
  std::vector<Number> values = {};
  std::vector<std::string> texts = {};

  std::uint64_t elements() const;
};

// Tables numbered in layout order (group by group): how blocks name their table in checkpoints.
class TableIndex {
 public:
  explicit TableIndex(const ResultLayout& layout);
  std::uint32_t find(const std::string& group, const std::string& table) const;  // throws std::logic_error
  const Table& table(std::uint32_t index) const { return tables_[index]; }
  const std::string& group_of(std::uint32_t index) const { return groups_[index]; }
  std::uint32_t size() const { return std::uint32_t(tables_.size()); }

 private:
  // Ordered by (group, table) name; looked up by views, so that finding a block's table copies no name.
  struct NameLess {
    using is_transparent = void;
    template <class A, class B>
    bool operator()(const A& a, const B& b) const {
      return std::pair<std::string_view, std::string_view>(a.first, a.second) <
             std::pair<std::string_view, std::string_view>(b.first, b.second);
    }
  };
  std::vector<Table> tables_;
  std::vector<std::string> groups_;
  std::map<std::pair<std::string, std::string>, std::uint32_t, NameLess> by_name_;
};

// The type of each number of an element, in order: the table's type, or its numeric fields' types.
std::vector<ValueType> number_types(const Table& table);

// Throws std::logic_error (a bug in the job kind) when a block does not fit its table's declaration: its
// shape, its counts of numbers and texts, or a number its element type does not hold.
void check_block(const Block& block, const Table& table);

}  // namespace pbrfit::store
