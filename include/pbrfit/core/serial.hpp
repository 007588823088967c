#pragma once
// One serialization mechanism for everything a job kind sends between ranks or keeps in a checkpoint:
// stage contexts, item inputs, results. `to_bytes(value)` and `from_bytes<T>(bytes)` handle
//  - arithmetic types and enums (little-endian, as they are in memory), bool as one byte;
//  - std::string, std::vector, std::array, std::pair, std::optional of anything handled;
//  - a struct that lists its members once, for both directions:
//        template <class Archive> void serialize(Archive& archive) { archive(scale, bias, evaluations); }
//    The writer calls it on a const value through const_cast and only reads the members.
// Vectors of arithmetic values are one length-prefixed block (ByteWriter::put_array), so a Bytes field
// or a std::vector<double> costs no more than when written by hand. Reading is bounds-checked and must
// consume the whole buffer: a short, long or implausible buffer throws ByteFormatError.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "pbrfit/core/bytes.hpp"

namespace pbrfit {

class SerialWriter;
class SerialReader;

// How one type is written and read; specialize it for a type that cannot have a serialize() member.
template <class T, class = void>
struct Serial;

namespace serial_detail {

template <class T>
inline constexpr bool is_plain = (std::is_arithmetic_v<T> || std::is_enum_v<T>) && !std::is_same_v<T, bool>;

template <class T, class = void>
struct has_serialize : std::false_type {};
template <class T>
struct has_serialize<T, std::void_t<decltype(std::declval<T&>().serialize(std::declval<SerialWriter&>()))>>
    : std::true_type {};

}  // namespace serial_detail

class SerialWriter {
 public:
  template <class... T>
  void operator()(const T&... values) {
    (Serial<T>::write(*this, values), ...);
  }
  ByteWriter& bytes() { return out_; }
  Bytes take() { return out_.take(); }

 private:
  ByteWriter out_;
};

class SerialReader {
 public:
  explicit SerialReader(std::span<const std::byte> bytes) : in_(bytes) {}
  template <class... T>
  void operator()(T&... values) {
    ((values = Serial<T>::read(*this)), ...);
  }
  ByteReader& bytes() { return in_; }

 private:
  ByteReader in_;
};

template <class T>
struct Serial<T, std::enable_if_t<serial_detail::is_plain<T>>> {
  static void write(SerialWriter& w, const T& value) { w.bytes().put(value); }
  static T read(SerialReader& r) { return r.bytes().get<T>(); }
};

template <>
struct Serial<bool> {
  static void write(SerialWriter& w, bool value) { w.bytes().put(std::uint8_t(value ? 1 : 0)); }
  static bool read(SerialReader& r) {
    const auto byte = r.bytes().get<std::uint8_t>();
    if (byte > 1) throw ByteFormatError(r.bytes().offset() - 1, "a boolean that is neither 0 nor 1");
    return byte == 1;
  }
};

template <>
struct Serial<std::byte> {
  static void write(SerialWriter& w, std::byte value) { w.bytes().put(value); }
  static std::byte read(SerialReader& r) { return r.bytes().get<std::byte>(); }
};

template <>
struct Serial<std::string> {
  static void write(SerialWriter& w, const std::string& value) { w.bytes().put_string(value); }
  static std::string read(SerialReader& r) { return r.bytes().get_string(); }
};

template <class T, class A>
struct Serial<std::vector<T, A>> {
  static void write(SerialWriter& w, const std::vector<T, A>& values) {
    if constexpr (serial_detail::is_plain<T> || std::is_same_v<T, std::byte>) {
      w.bytes().put_array(std::span<const T>(values));
    } else {
      w.bytes().put<std::uint64_t>(values.size());
      for (const auto& value : values) Serial<T>::write(w, value);
    }
  }
  static std::vector<T, A> read(SerialReader& r) {
    if constexpr (serial_detail::is_plain<T> || std::is_same_v<T, std::byte>) {
      auto values = r.bytes().get_array<T>();
      if constexpr (std::is_same_v<A, std::allocator<T>>) return values;  // no second copy
      else return {values.begin(), values.end()};
    } else {
      const auto count = r.bytes().get<std::uint64_t>();
      // Every element takes at least one byte: a count beyond the data is a corrupt buffer, not an allocation.
      if (count > r.bytes().remaining()) throw ByteFormatError(r.bytes().offset(), "array length exceeds the data");
      std::vector<T, A> values;
      values.reserve(count);
      for (std::uint64_t i = 0; i < count; ++i) values.push_back(Serial<T>::read(r));
      return values;
    }
  }
};

template <class T, std::size_t N>
struct Serial<std::array<T, N>> {
  static void write(SerialWriter& w, const std::array<T, N>& values) {
    for (const auto& value : values) Serial<T>::write(w, value);
  }
  static std::array<T, N> read(SerialReader& r) {
    std::array<T, N> values{};
    for (auto& value : values) value = Serial<T>::read(r);
    return values;
  }
};

template <class A, class B>
struct Serial<std::pair<A, B>> {
  static void write(SerialWriter& w, const std::pair<A, B>& value) { w(value.first, value.second); }
  static std::pair<A, B> read(SerialReader& r) {
    std::pair<A, B> value;
    r(value.first, value.second);
    return value;
  }
};

template <class T>
struct Serial<std::optional<T>> {
  static void write(SerialWriter& w, const std::optional<T>& value) {
    Serial<bool>::write(w, value.has_value());
    if (value) Serial<T>::write(w, *value);
  }
  static std::optional<T> read(SerialReader& r) {
    if (!Serial<bool>::read(r)) return std::nullopt;
    return Serial<T>::read(r);
  }
};

template <class T>
struct Serial<T, std::enable_if_t<serial_detail::has_serialize<T>::value>> {
  static void write(SerialWriter& w, const T& value) { const_cast<T&>(value).serialize(w); }
  static T read(SerialReader& r) {
    T value{};
    value.serialize(r);
    return value;
  }
};

// A struct with nothing to send: the context or input of a stage that needs none.
struct Nothing {
  template <class Archive>
  void serialize(Archive&) {}
};

template <class T>
Bytes to_bytes(const T& value) {
  SerialWriter w;
  Serial<T>::write(w, value);
  return w.take();
}

template <class T>
T from_bytes(std::span<const std::byte> bytes) {
  SerialReader r(bytes);
  T value = Serial<T>::read(r);
  if (r.bytes().remaining() != 0) throw ByteFormatError(r.bytes().offset(), "data continues past its end");
  return value;
}

}  // namespace pbrfit
