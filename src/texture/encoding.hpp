#pragma once
// What every encoder of the texture module shares (private): the checks and refusals that start with the
// format's name, little-endian byte output, the value conversions of texture.hpp (double -> float, then
// Imath's half), the text entries formats hold beside the metadata, and quoting for comments.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pbrfit/core/bytes.hpp"
#include "pbrfit/texture/texture.hpp"

namespace pbrfit::texture::detail {

// std::invalid_argument("FORMAT: why").
[[noreturn]] void refuse(std::string_view format, const std::string& why);
// validate(t), its message prefixed with "FORMAT: ".
void check_texture(const Texture& t, std::string_view format);
// Refuses array layers, a depth above 1 and mip levels: "FORMAT: holds one 2D image, not 6 mip levels".
void require_one_image(const Texture& t, std::string_view format);
// "level 0, layer 2, texel (3, 1), channel G" (z only for volumes, layer only for arrays) of values[index].
std::string texel_of(const Texture& t, std::size_t index);

// %.17g: the double read back exactly; "inf", "nan" as C prints them.
std::string number(double v);

float to_float(double v);
std::uint32_t float_bits(double v);
std::uint16_t half_bits(double v);
float half_rounded(double v);  // the float equal to the half of v
inline constexpr std::uint16_t half_one = 0x3c00;

// The entries text-holding formats write: ("name", name), ("channels", "a,b,c"), then the metadata.
std::vector<std::pair<std::string, std::string>> text_entries(const Texture& t);
// "..." with \\, \", \n, \r, \t and \xNN for every other byte outside printable ASCII: safe in any line
// comment and never ending in a backslash.
std::string quoted(std::string_view text);

void put_u8(Bytes& out, std::uint8_t v);
void put_u16(Bytes& out, std::uint16_t v);
void put_u32(Bytes& out, std::uint32_t v);
void put_u64(Bytes& out, std::uint64_t v);
void put_text(Bytes& out, std::string_view text);
void put_zeros(Bytes& out, std::size_t count);
void set_u32(Bytes& out, std::size_t at, std::uint32_t v);
void set_u64(Bytes& out, std::size_t at, std::uint64_t v);
Bytes as_bytes(std::string_view text);

}  // namespace pbrfit::texture::detail
