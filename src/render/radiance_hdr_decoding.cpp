#include <algorithm>
#include <array>
#include <string_view>
#include <vector>

#include "pbrfit/core/error.hpp"
#include "pbrfit/render/radiance_hdr.hpp"
#include "rgbe.hpp"

namespace pbrfit::render {
namespace {

struct Size {
  std::size_t width = 0, height = 0;
};

// The fewest bytes a scanline of this width can take: flat, or runs of 127 for each component.
std::size_t least_scanline_bytes(std::size_t width) {
  const std::size_t flat = 4 * width;
  return run_length_width(width) ? std::min(flat, 4 + 4 * 2 * ((width + 126) / 127)) : flat;
}

// Reads the bytes front to back; every failure names the file and the offset.
class HdrReader {
 public:
  HdrReader(std::span<const std::byte> bytes, const std::string& name) : bytes_(bytes), name_(name) {}

  RgbImage read() {
    read_signature();
    read_variables();
    const Size size = read_resolution();
    RgbImage image(size.width, size.height);
    std::vector<Rgbe> scanline(size.width);
    for (std::size_t row = 0; row < size.height; ++row) {
      read_scanline(row, scanline);
      for (std::size_t column = 0; column < size.width; ++column) image.set(column, row, rgb_of(scanline[column]));
    }
    return image;
  }

 private:
  [[noreturn]] void fail(std::size_t offset, const std::string& what) const {
    throw InputError({name_, 0, 0}, what + " at byte " + std::to_string(offset));
  }

  std::size_t remaining() const { return bytes_.size() - at_; }
  std::uint8_t byte_at(std::size_t offset) const { return std::uint8_t(bytes_[offset]); }

  // The next line without its newline (and a carriage return before it).
  std::string_view line() {
    const std::size_t start = at_;
    const auto* begin = reinterpret_cast<const char*>(bytes_.data());
    const auto* newline = std::find(begin + start, begin + bytes_.size(), '\n');
    if (newline == begin + bytes_.size()) fail(bytes_.size(), "the header ends without a resolution line");
    at_ = std::size_t(newline - begin) + 1;
    std::string_view text(begin + start, std::size_t(newline - begin) - start);
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    return text;
  }

  void read_signature() {
    const bool hdr = remaining() >= 2 && byte_at(0) == '#' && byte_at(1) == '?';
    const std::string_view first = hdr ? line() : std::string_view();
    if (first != "#?RADIANCE" && first != "#?RGBE")
      fail(0, "is not a Radiance HDR picture: it does not start with the line #?RADIANCE or #?RGBE");
  }

  void read_variables() {
    for (;;) {
      const std::size_t start = at_;
      const std::string_view text = line();
      if (text.empty()) return;
      if (text.starts_with("FORMAT=") && text != "FORMAT=32-bit_rle_rgbe")
        fail(start, "the pixel format '" + std::string(text.substr(0, 40)) + "' is not supported (only 32-bit_rle_rgbe)");
    }
  }

  Size read_resolution();
  std::size_t dimension(std::string_view digits, std::size_t start) const;
  void read_scanline(std::size_t row, std::vector<Rgbe>& pixels);
  void read_flat(std::size_t row, std::vector<Rgbe>& pixels);
  void read_runs(std::size_t row, std::vector<Rgbe>& pixels);
  std::uint8_t take(std::size_t row) {
    if (remaining() == 0) fail(bytes_.size(), "the data ends inside scanline " + std::to_string(row));
    return byte_at(at_++);
  }

  std::span<const std::byte> bytes_;
  const std::string& name_;
  std::size_t at_ = 0;
};

std::vector<std::string_view> words(std::string_view text) {
  std::vector<std::string_view> out;
  while (!text.empty()) {
    const std::size_t start = text.find_first_not_of(" \t");
    if (start == std::string_view::npos) break;
    const std::size_t end = std::min(text.find_first_of(" \t", start), text.size());
    out.push_back(text.substr(start, end - start));
    text.remove_prefix(end);
  }
  return out;
}

bool is_axis(std::string_view word) { return word == "-Y" || word == "+Y" || word == "-X" || word == "+X"; }

std::size_t HdrReader::dimension(std::string_view digits, std::size_t start) const {
  if (digits.size() > 9) fail(start, "the dimension " + std::string(digits.substr(0, 12)) + "... is too large");
  std::size_t value = 0;
  for (char c : digits) value = 10 * value + std::size_t(c - '0');
  if (value == 0) fail(start, "the picture has no pixels (a dimension is 0)");
  return value;
}

Size HdrReader::read_resolution() {
  const std::size_t start = at_;
  const std::string_view text = line();
  const auto w = words(text);
  const auto numeric = [](std::string_view s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
  };
  if (w.size() != 4 || !is_axis(w[0]) || !is_axis(w[2]) || w[0][1] == w[2][1] || !numeric(w[1]) || !numeric(w[3]))
    fail(start, "the resolution line '" + std::string(text.substr(0, 40)) + "' is not understood (expected -Y HEIGHT +X WIDTH)");
  if (w[0] != "-Y" || w[2] != "+X")
    fail(start, "the orientation '" + std::string(text.substr(0, 40)) +
                    "' is not supported (only -Y HEIGHT +X WIDTH: rows from the top, columns from the left)");
  const Size size{dimension(w[3], start), dimension(w[1], start)};
  if (size.width * size.height > max_hdr_texels)
    fail(start, "the picture of " + std::to_string(size.width) + " x " + std::to_string(size.height) +
                    " texels is larger than the " + std::to_string(max_hdr_texels) + " read at most");
  if (remaining() / size.height < least_scanline_bytes(size.width))
    fail(bytes_.size(), "the data ends before the " + std::to_string(size.height) + " scanlines of " +
                            std::to_string(size.width) + " pixels the resolution line declares");
  return size;
}

void HdrReader::read_scanline(std::size_t row, std::vector<Rgbe>& pixels) {
  const bool runs = run_length_width(pixels.size()) && remaining() >= 4 && byte_at(at_) == 2 && byte_at(at_ + 1) == 2 &&
                    (byte_at(at_ + 2) & 0x80) == 0;
  if (runs) return read_runs(row, pixels);
  read_flat(row, pixels);
}

void HdrReader::read_flat(std::size_t row, std::vector<Rgbe>& pixels) {
  if (remaining() / 4 < pixels.size()) fail(bytes_.size(), "the data ends inside scanline " + std::to_string(row));
  for (Rgbe& p : pixels)
    for (std::uint8_t& component : p) component = byte_at(at_++);
}

void HdrReader::read_runs(std::size_t row, std::vector<Rgbe>& pixels) {
  const std::size_t start = at_;
  const std::size_t declared = std::size_t(byte_at(at_ + 2)) << 8 | byte_at(at_ + 3);
  if (declared != pixels.size())
    fail(start, "scanline " + std::to_string(row) + " declares " + std::to_string(declared) + " pixels; the picture is " +
                    std::to_string(pixels.size()) + " wide");
  at_ += 4;
  for (std::size_t component = 0; component < 4; ++component) {
    for (std::size_t filled = 0; filled < pixels.size();) {
      const std::size_t count_at = at_;
      const std::size_t count = take(row);
      const bool repeat = count > 128;
      const std::size_t length = repeat ? count - 128 : count;
      if (length == 0) fail(count_at, "scanline " + std::to_string(row) + " has a run of length 0");
      if (filled + length > pixels.size())
        fail(count_at, "a run of scanline " + std::to_string(row) + " goes past the end of the scanline");
      const std::uint8_t value = repeat ? take(row) : 0;
      for (std::size_t i = 0; i < length; ++i) pixels[filled + i][component] = repeat ? value : take(row);
      filled += length;
    }
  }
}

}  // namespace

RgbImage decode_radiance_hdr(std::span<const std::byte> bytes, const std::string& name) {
  return HdrReader(bytes, name).read();
}

}  // namespace pbrfit::render
