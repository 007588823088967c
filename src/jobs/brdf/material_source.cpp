#include "pbrfit/jobs/brdf/material_source.hpp"

#include <unistd.h>

#include <filesystem>

#include "pbrfit/brdf/neural_brdf.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/store/share_directory.hpp"
#include "pbrfit/store/merl_file.hpp"
#include "pbrfit/store/result_file.hpp"

namespace pbrfit::jobs::brdf {
namespace {

std::vector<double> weights(const std::string& path, int layer, const char* what) {
  const std::string name = "/dense_" + std::to_string(layer) + "/dense_" + std::to_string(layer) + "/" + what + ":0";
  try {
    return store::read_table(path, name);
  } catch (const RunError& e) {
    throw InputError({path}, "is not a neural stand-in: " + std::string(e.what()));
  }
}

pbrfit::brdf::MerlTable stand_in(const std::string& path) {
  if (access(path.c_str(), R_OK) != 0) throw InputError({path}, "cannot read the stand-in of this material");
  pbrfit::brdf::NeuralBrdfWeights w{weights(path, 1, "kernel"), weights(path, 1, "bias"), weights(path, 2, "kernel"),
                                    weights(path, 2, "bias"),   weights(path, 3, "kernel"), weights(path, 3, "bias")};
  try {
    return pbrfit::brdf::NeuralBrdf(std::move(w)).tabulate();
  } catch (const std::invalid_argument& e) {
    throw InputError({path}, e.what());
  }
}

pbrfit::brdf::MerlTable from_file(const std::string& path) {
  try {
    return pbrfit::brdf::merl_table_from_stored(store::read_merl_file(path));
  } catch (const std::invalid_argument& e) {
    throw InputError({path}, e.what());
  }
}

// The cache only saves time: a directory that cannot be made or written leaves the table uncached.
void write_cache(const std::string& path, const std::vector<double>& stored) {
  std::error_code ignored;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ignored);
  try {
    store::write_merl_file(path, stored);
  } catch (const RunError&) {
  }
}

std::string standin_directory(const MaterialSource& source) {
  return source.standins.empty() ? store::data_directory() + "/merl_nbrdf" : source.standins;
}

}  // namespace

std::string material_path(const std::string& name, const MaterialSource& source) {
  return source.merl_directory.empty() ? standin_directory(source) + "/" + name + ".h5" : source.merl_directory + "/" + name + ".binary";
}

pbrfit::brdf::MerlTable load_material(const std::string& name, const MaterialSource& source) {
  if (!source.merl_directory.empty()) return from_file(source.merl_directory + "/" + name + ".binary");
  const std::string cached = source.cache_directory.empty() ? "" : source.cache_directory + "/" + name + ".binary";
  if (!cached.empty() && access(cached.c_str(), R_OK) == 0) return from_file(cached);
  // Through the stored form either way, so a cached and an uncached run see the very same numbers.
  const auto stored = pbrfit::brdf::stored_from_merl_table(stand_in(standin_directory(source) + "/" + name + ".h5"));
  if (!cached.empty()) write_cache(cached, stored);
  return pbrfit::brdf::merl_table_from_stored(stored);
}

}  // namespace pbrfit::jobs::brdf
