#pragma once
// A number of a result block: a real (double) or an exact integer, signed or unsigned, of up to 64 bits.
// It is made from whatever C++ number a kind has (Number(0.5), Number(std::size_t{7}), Number(-3)), and keeps
// what it was made from, so integers reach the result file, the journal and checkpoints as integers:
// an integer table or field (int32, int64, uint8, uint32, uint64) takes only integers its type can hold
// (check_block refuses anything else as a bug in the kind), and a real table or field takes either (an
// integer is converted to double, as C++ would).
#include <bit>
#include <concepts>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

namespace pbrfit::store {

class Number {
 public:
  enum class Kind : std::uint8_t { real, signed_integer, unsigned_integer };

  constexpr Number() = default;  // the real 0.0
  constexpr Number(double real) : bits_(std::bit_cast<std::uint64_t>(real)) {}
  template <std::integral T>
    requires(!std::same_as<T, bool>)
  constexpr Number(T integer) {
    if constexpr (std::is_signed_v<T>) {
      kind_ = Kind::signed_integer;
      bits_ = std::uint64_t(std::int64_t(integer));
    } else {
      kind_ = Kind::unsigned_integer;
      bits_ = std::uint64_t(integer);
    }
  }
  Number(bool) = delete;  // say 0 or 1, as an integer

  constexpr Kind kind() const { return kind_; }
  constexpr bool is_integer() const { return kind_ != Kind::real; }
  // The value as a double (an integer converted, rounded beyond 2^53).
  constexpr double real() const {
    switch (kind_) {
      case Kind::signed_integer: return double(std::int64_t(bits_));
      case Kind::unsigned_integer: return double(bits_);
      default: return std::bit_cast<double>(bits_);
    }
  }
  // The integer (call only when is_integer()).
  constexpr std::int64_t signed_value() const { return std::int64_t(bits_); }
  constexpr std::uint64_t unsigned_value() const { return bits_; }
  constexpr bool negative() const { return kind_ == Kind::signed_integer && std::int64_t(bits_) < 0; }

  // The same kind and the same bits: a NaN equals itself, 0.0 differs from -0.0, an integer 1 from the real 1.0.
  friend constexpr bool operator==(const Number&, const Number&) = default;

 private:
  std::uint64_t bits_ = 0;
  Kind kind_ = Kind::real;
};

// Doubles as the values of a block.
inline std::vector<Number> reals(std::span<const double> values) { return {values.begin(), values.end()}; }

}  // namespace pbrfit::store
