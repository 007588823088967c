#pragma once
// MERL BRDF files (`.binary`, Matusik et al. 2003), as stored: three little-endian int32 dimensions
// (90, 90, 180: theta_h, theta_d, phi_d), then 3 x 1,458,000 little-endian float64 values, all red, all
// green, all blue, before the MERL channel scales. Negative values mark unmeasured cells (they are data
// for the reader, missing values for whoever uses the table; brdf/merl_table.hpp converts).
//
// Contract: read_merl_file accepts only a regular file of exactly the right size with those dimensions and
// finite values, and otherwise throws InputError naming the file and, for a bad value, its byte offset
// and channel; write_merl_file replaces the file atomically (atomic_file.hpp) and throws RunError.
#include <string>
#include <vector>

namespace pbrfit::store {

inline constexpr std::size_t merl_value_count = 3 * 90 * 90 * 180;
inline constexpr std::size_t merl_file_bytes = 12 + 8 * merl_value_count;

std::vector<double> read_merl_file(const std::string& path);
void write_merl_file(const std::string& path, const std::vector<double>& stored_values);

}  // namespace pbrfit::store
