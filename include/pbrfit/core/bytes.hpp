#pragma once
// Byte buffers for work-item results, stage contexts and checkpoints: little-endian, length-checked.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace pbrfit {

using Bytes = std::vector<std::byte>;

// Appends trivially copyable values and length-prefixed arrays and strings.
class ByteWriter {
 public:
  template <class T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    append(&value, sizeof(T));
  }
  template <class T>
  void put_array(std::span<const T> values) {
    static_assert(std::is_trivially_copyable_v<T>);
    put<std::uint64_t>(values.size());
    append(values.data(), values.size_bytes());
  }
  // Unsigned LEB128: 7 bits a byte, small values in one byte.
  void put_varint(std::uint64_t value) {
    while (value >= 0x80) {
      put(std::uint8_t(value | 0x80));
      value >>= 7;
    }
    put(std::uint8_t(value));
  }
  // Signed, zigzag-coded (0, -1, 1, -2, ... as 0, 1, 2, 3, ...): small magnitudes in one byte.
  void put_signed_varint(std::int64_t value) {
    put_varint((std::uint64_t(value) << 1) ^ (value < 0 ? ~std::uint64_t(0) : 0));
  }
  void put_string(const std::string& s) {
    put_array(std::span<const char>(s.data(), s.size()));
  }
  void put_bytes(const Bytes& b) { put_array(std::span<const std::byte>(b)); }
  // Appends bytes as they are, without a length: a copy of what another writer encoded.
  void put_raw(std::span<const std::byte> b) { append(b.data(), b.size()); }
  const Bytes& bytes() const { return bytes_; }
  Bytes take() { return std::move(bytes_); }

 private:
  void append(const void* data, std::size_t size) {
    const std::size_t old = bytes_.size();
    bytes_.resize(old + size);
    if (size > 0) std::memcpy(bytes_.data() + old, data, size);
  }
  Bytes bytes_;
};

// Thrown when a buffer ends early or a length is implausible; callers add the file name.
class ByteFormatError : public std::runtime_error {
 public:
  ByteFormatError(std::size_t offset, const std::string& what)
      : std::runtime_error(what), offset_(offset) {}
  std::size_t offset() const { return offset_; }

 private:
  std::size_t offset_;
};

// Reads what ByteWriter wrote; every read is bounds-checked.
class ByteReader {
 public:
  explicit ByteReader(std::span<const std::byte> bytes) : bytes_(bytes) {}

  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    require(sizeof(T));
    T value;
    std::memcpy(&value, bytes_.data() + offset_, sizeof(T));
    offset_ += sizeof(T);
    return value;
  }
  template <class T>
  std::vector<T> get_array() {
    const auto count = get<std::uint64_t>();
    if (count > remaining() / sizeof(T)) throw ByteFormatError(offset_, "array length exceeds the data");
    std::vector<T> values(count);
    // An empty vector's data() may be null, and memcpy from or to null is undefined even for 0 bytes.
    if (count > 0) std::memcpy(values.data(), bytes_.data() + offset_, count * sizeof(T));
    offset_ += count * sizeof(T);
    return values;
  }
  std::uint64_t get_varint() {
    std::uint64_t value = 0;
    for (int shift = 0; shift < 64; shift += 7) {
      const auto byte = get<std::uint8_t>();
      value |= std::uint64_t(byte & 0x7f) << shift;
      if (!(byte & 0x80)) return value;
    }
    throw ByteFormatError(offset_, "variable-length integer longer than 64 bits");
  }
  std::int64_t get_signed_varint() {
    const std::uint64_t coded = get_varint();
    return std::int64_t((coded >> 1) ^ (~(coded & 1) + 1));
  }
  std::string get_string() {
    auto chars = get_array<char>();
    return {chars.begin(), chars.end()};
  }
  Bytes get_bytes() { return get_array<std::byte>(); }

  std::size_t offset() const { return offset_; }
  std::size_t remaining() const { return bytes_.size() - offset_; }

 private:
  void require(std::size_t n) const {
    if (n > remaining()) throw ByteFormatError(offset_, "data ends early");
  }
  std::span<const std::byte> bytes_;
  std::size_t offset_ = 0;
};

// FNV-1a, 64 bit: the checksum of checkpoint files.
std::uint64_t fnv1a64(std::span<const std::byte> bytes);

}  // namespace pbrfit
