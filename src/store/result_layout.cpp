#include "pbrfit/store/result_layout.hpp"

#include <limits>
#include <numeric>
#include <stdexcept>

namespace pbrfit::store {

bool is_numeric(ValueType type) { return type != ValueType::text; }

bool is_integer(ValueType type) { return is_numeric(type) && type != ValueType::f32 && type != ValueType::f64; }

bool is_signed_integer(ValueType type) { return type == ValueType::i32 || type == ValueType::i64; }

bool holds(ValueType type, const Number& number) {
  if (!is_integer(type)) return is_numeric(type);
  if (!number.is_integer()) return false;
  if (number.negative()) {
    const std::int64_t value = number.signed_value();
    return type == ValueType::i64 || (type == ValueType::i32 && value >= std::numeric_limits<std::int32_t>::min());
  }
  const std::uint64_t value = number.unsigned_value();
  switch (type) {
    case ValueType::i32: return value <= std::uint64_t(std::numeric_limits<std::int32_t>::max());
    case ValueType::i64: return value <= std::uint64_t(std::numeric_limits<std::int64_t>::max());
    case ValueType::u8: return value <= std::numeric_limits<std::uint8_t>::max();
    case ValueType::u32: return value <= std::numeric_limits<std::uint32_t>::max();
    default: return true;
  }
}

const char* type_name(ValueType type) {
  switch (type) {
    case ValueType::f32: return "float32";
    case ValueType::f64: return "float64";
    case ValueType::i32: return "int32";
    case ValueType::i64: return "int64";
    case ValueType::u8: return "uint8";
    case ValueType::u32: return "uint32";
    case ValueType::u64: return "uint64";
    default: return "string";
  }
}

std::size_t Table::numbers_per_element() const {
  if (!is_record()) return is_numeric(type) ? 1 : 0;
  std::size_t n = 0;
  for (const auto& f : fields) n += is_numeric(f.type);
  return n;
}

std::size_t Table::texts_per_element() const {
  if (!is_record()) return is_numeric(type) ? 0 : 1;
  return fields.size() - numbers_per_element();
}

const Axis& Group::axis(const std::string& axis_name) const {
  for (const auto& a : axes)
    if (a.name == axis_name) return a;
  throw std::logic_error("group '" + name + "' has no axis '" + axis_name + "'");
}

std::uint64_t Block::elements() const {
  return std::accumulate(count.begin(), count.end(), std::uint64_t{1}, std::multiplies<>());
}

TableIndex::TableIndex(const ResultLayout& layout) {
  for (const auto& group : layout.groups) {
    for (const auto& table : group.tables) {
      by_name_[{group.name, table.name}] = std::uint32_t(tables_.size());
      tables_.push_back(table);
      groups_.push_back(group.name);
    }
  }
}

std::uint32_t TableIndex::find(const std::string& group, const std::string& table) const {
  const auto found = by_name_.find(std::pair<std::string_view, std::string_view>(group, table));
  if (found == by_name_.end()) throw std::logic_error("no table " + group + "/" + table + " in the layout");
  return found->second;
}

std::vector<ValueType> number_types(const Table& table) {
  if (!table.is_record()) return is_numeric(table.type) ? std::vector<ValueType>{table.type} : std::vector<ValueType>{};
  std::vector<ValueType> types;
  for (const auto& f : table.fields)
    if (is_numeric(f.type)) types.push_back(f.type);
  return types;
}

void check_block(const Block& block, const Table& table) {
  const std::string where = block.group + "/" + block.table;
  if (block.offset.size() != table.axes.size() || block.count.size() != table.axes.size())
    throw std::logic_error("block for " + where + " has the wrong number of dimensions");
  const std::uint64_t n = block.elements();
  if (block.values.size() != n * table.numbers_per_element() || block.texts.size() != n * table.texts_per_element())
    throw std::logic_error("block for " + where + " holds the wrong number of values");
  const std::vector<ValueType> types = number_types(table);
  for (std::size_t i = 0; i < block.values.size(); ++i) {
    const ValueType type = types[i % types.size()];
    if (!holds(type, block.values[i]))
      throw std::logic_error("block for " + where + " puts " +
                             (block.values[i].is_integer() ? "an integer out of the range of" : "a real into") + " a " +
                             type_name(type) + " element (number " + std::to_string(i) + ")");
  }
}

}  // namespace pbrfit::store
