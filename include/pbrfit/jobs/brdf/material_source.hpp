#pragma once
// Where a measured material comes from, by MERL name: `<merl_directory>/<name>.binary` when a directory of
// real MERL files is given, else the neural stand-in `<standins>/<name>.h5` (default: merl_nbrdf in the
// data directory, store/share_directory.hpp) evaluated on the MERL grid, optionally cached as
// `<cache_directory>/<name>.binary` (a later job reads the cache).
//
// Contract: load_material returns a table of the MERL grid or throws InputError naming the file (missing,
// malformed, another size). A cache that cannot be written is skipped (it only saves time); concurrent
// writers of one cache file are safe (each writes its own temporary, then renames). A stand-in's table is
// bitwise the same with and without the cache (both pass through the stored form).
#include <string>

#include "pbrfit/brdf/merl_table.hpp"

namespace pbrfit::jobs::brdf {

// Where job files keep the tabulated stand-ins unless they say otherwise (their `cache` key).
inline constexpr const char* default_material_cache = "results/merl-cache";

struct MaterialSource {
  std::string merl_directory;   // empty: use the stand-ins
  std::string standins;          // empty: data_directory() + "/merl_nbrdf"
  std::string cache_directory;  // empty: no cache
};

pbrfit::brdf::MerlTable load_material(const std::string& name, const MaterialSource& source);
// The file a material is read from when it is not cached: the .binary or the stand-in.
std::string material_path(const std::string& name, const MaterialSource& source);

}  // namespace pbrfit::jobs::brdf
