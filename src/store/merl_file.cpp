#include "pbrfit/store/merl_file.hpp"

#include <bit>
#include <cmath>
#include <cstring>

#include "pbrfit/core/bytes.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/store/atomic_file.hpp"

namespace pbrfit::store {
namespace {

static_assert(std::endian::native == std::endian::little, "MERL files are little-endian; so must the host be");

constexpr std::int32_t dimensions[3] = {90, 90, 180};
const char* channel_names[3] = {"red", "green", "blue"};

}  // namespace

std::vector<double> read_merl_file(const std::string& path) {
  const Bytes bytes = read_whole_file(path, merl_file_bytes);
  if (bytes.size() != merl_file_bytes)
    throw InputError({path}, "is " + std::to_string(bytes.size()) + " bytes long; a MERL file has " +
                                 std::to_string(merl_file_bytes));
  std::int32_t header[3];
  std::memcpy(header, bytes.data(), sizeof header);
  if (header[0] != dimensions[0] || header[1] != dimensions[1] || header[2] != dimensions[2])
    throw InputError({path}, "has the dimensions " + std::to_string(header[0]) + " x " + std::to_string(header[1]) +
                                 " x " + std::to_string(header[2]) + "; a MERL file has 90 x 90 x 180");
  std::vector<double> values(merl_value_count);
  std::memcpy(values.data(), bytes.data() + 12, 8 * merl_value_count);
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      throw InputError({path}, "holds a value that is not a finite number at byte " + std::to_string(12 + 8 * i) + " (" +
                                   channel_names[i / (merl_value_count / 3)] + " channel, cell " +
                                   std::to_string(i % (merl_value_count / 3)) + ")");
  return values;
}

void write_merl_file(const std::string& path, const std::vector<double>& values) {
  if (values.size() != merl_value_count) throw RunError("a MERL table needs " + std::to_string(merl_value_count) + " values");
  Bytes bytes(merl_file_bytes);
  std::memcpy(bytes.data(), dimensions, sizeof dimensions);
  std::memcpy(bytes.data() + 12, values.data(), 8 * merl_value_count);
  replace_file_atomically(path, bytes);
}

}  // namespace pbrfit::store
