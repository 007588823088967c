#include "element_types.hpp"

#include <cstring>

namespace pbrfit::store {

using h5::check;
using h5::Handle;

namespace {

constexpr std::size_t slot = 8;  // bytes per value in memory: a double, a 64-bit integer or a char*
static_assert(sizeof(double) == slot && sizeof(std::uint64_t) == slot && sizeof(const char*) == slot);


Handle copy_of(hid_t type) { return Handle(check(H5Tcopy(type), "copy a datatype"), H5Tclose); }

Handle file_value_type(ValueType type) {
  switch (type) {
    case ValueType::f32: return copy_of(H5T_IEEE_F32LE);
    case ValueType::f64: return copy_of(H5T_IEEE_F64LE);
    case ValueType::i32: return copy_of(H5T_STD_I32LE);
    case ValueType::i64: return copy_of(H5T_STD_I64LE);
    case ValueType::u8: return copy_of(H5T_STD_U8LE);
    case ValueType::u32: return copy_of(H5T_STD_U32LE);
    case ValueType::u64: return copy_of(H5T_STD_U64LE);
    default: return h5::string_type();
  }
}

// Reals as doubles, integers as 64-bit integers of their signedness (HDF5 narrows them exactly: check_block
// has made sure each fits), texts as char*.
Handle memory_value_type(ValueType type) {
  if (!is_numeric(type)) return h5::string_type();
  if (!is_integer(type)) return copy_of(H5T_NATIVE_DOUBLE);
  return copy_of(is_signed_integer(type) ? H5T_NATIVE_INT64 : H5T_NATIVE_UINT64);
}

template <class ValueTypeOf>
Handle record_type(const Table& table, std::size_t (*size_of)(const Handle&), ValueTypeOf value_type) {
  std::vector<Handle> members;
  std::size_t size = 0;
  for (const auto& field : table.fields) {
    members.push_back(value_type(field.type));
    size += size_of(members.back());
  }
  Handle record(check(H5Tcreate(H5T_COMPOUND, size), "create a record type"), H5Tclose);
  std::size_t offset = 0;
  for (std::size_t i = 0; i < members.size(); ++i) {
    check(H5Tinsert(record, table.fields[i].name.c_str(), offset, members[i]), "add field " + table.fields[i].name);
    offset += size_of(members[i]);
  }
  return record;
}

std::size_t packed_size(const Handle& type) { return H5Tget_size(type); }
std::size_t slot_size(const Handle&) { return slot; }

}  // namespace

Handle file_type_of(const Table& table) {
  return table.is_record() ? record_type(table, packed_size, file_value_type) : file_value_type(table.type);
}

Handle memory_type_of(const Table& table) {
  return table.is_record() ? record_type(table, slot_size, memory_value_type) : memory_value_type(table.type);
}

std::vector<std::byte> pack_elements(const Table& table, const Block& block) {
  std::vector<std::byte> out;
  out.reserve(block.values.size() * slot + block.texts.size() * slot);
  const auto put = [&out](const void* value) {
    const auto* bytes = static_cast<const std::byte*>(value);
    out.insert(out.end(), bytes, bytes + slot);
  };
  std::size_t number = 0, text = 0;
  const auto put_value = [&](ValueType type) {
    if (is_integer(type)) {
      const Number& n = block.values[number++];
      const std::uint64_t bits = is_signed_integer(type) ? std::uint64_t(n.signed_value()) : n.unsigned_value();
      put(&bits);
    } else if (is_numeric(type)) {
      const double real = block.values[number++].real();
      put(&real);
    } else {
      const char* pointer = block.texts[text++].c_str();
      put(&pointer);
    }
  };
  for (std::uint64_t e = 0; e < block.elements(); ++e) {
    if (!table.is_record()) put_value(table.type);
    for (const auto& field : table.fields) put_value(field.type);
  }
  return out;
}

}  // namespace pbrfit::store
