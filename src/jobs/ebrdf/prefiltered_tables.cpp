#include "pbrfit/jobs/ebrdf/prefiltered_tables.hpp"

#include <algorithm>
#include <string>

#include "pbrfit/core/error.hpp"
#include "pbrfit/store/result_file.hpp"

namespace pbrfit::jobs::ebrdf {
namespace {

namespace eb = pbrfit::ebrdf;

std::vector<float> as_floats(const std::vector<double>& values) { return {values.begin(), values.end()}; }

std::shared_ptr<const eb::NormalMap> read_normals(const std::string& path) {
  std::vector<std::uint64_t> dims;
  const auto values = store::read_table(path, "ebrdf/normal_map/normal", &dims);
  if (dims.size() != 3 || dims[0] != dims[1] || dims[2] != 3 || !eb::is_power_of_two(dims[0]))
    throw InputError({path}, "ebrdf/normal_map/normal is not a square power-of-two map of normals");
  std::vector<Vector3> normals(dims[0] * dims[1]);
  for (std::size_t i = 0; i < normals.size(); ++i) normals[i] = {values[3 * i], values[3 * i + 1], values[3 * i + 2]};
  return std::make_shared<const eb::NormalMap>(dims[0], std::move(normals));
}

std::optional<eb::LtcMipTables> read_component(const std::string& path, const std::string& component) {
  const auto groups = store::read_group_names(path, "ebrdf");
  if (std::find(groups.begin(), groups.end(), component) == groups.end()) return std::nullopt;
  std::vector<eb::LtcLevel> levels;
  eb::ViewGrid views;
  const auto names = store::read_group_names(path, "ebrdf/" + component);
  for (std::size_t level = 1;; ++level) {
    const std::string group = "ebrdf/" + component + "/mip" + std::to_string(level);
    if (std::find(names.begin(), names.end(), "mip" + std::to_string(level)) == names.end()) break;
    std::vector<std::uint64_t> dims;
    eb::LtcLevel table;
    table.matrices = as_floats(store::read_table(path, group + "/matrix", &dims));
    table.amplitudes = as_floats(store::read_table(path, group + "/amplitude"));
    if (dims.size() != 5 || dims[0] != dims[1] || dims[4] != 9) throw InputError({path}, group + "/matrix has the wrong shape");
    table.side = dims[0];
    views = {dims[2], dims[3]};
    levels.push_back(std::move(table));
  }
  if (levels.empty()) throw InputError({path}, "ebrdf/" + component + " holds no mip level");
  try {
    return eb::LtcMipTables(views, std::move(levels),
                            component == "specular" ? eb::LobeAxis::mirror : eb::LobeAxis::normal);
  } catch (const std::invalid_argument& e) {
    throw InputError({path}, std::string("ebrdf/") + component + ": " + e.what());
  }
}

}  // namespace

namespace {

PrefilteredTables read_tables(const std::string& path) {
  const store::ResultSummary summary = store::read_result_summary(path);
  if (summary.job_kind != "ebrdf")
    throw InputError({path}, "is a result of kind '" + summary.job_kind + "', not of an ebrdf job");
  if (summary.state != store::RunStatus::complete)
    throw InputError({path}, "is " + store::run_status_name(summary.state) + ", not complete: finish (or --resume) its job first");
  PrefilteredTables tables;
  tables.map = read_normals(path);
  tables.specular = read_component(path, "specular");
  tables.diffuse = read_component(path, "diffuse");
  if (!tables.specular || !tables.diffuse)
    throw InputError({path}, "holds only one component; rendering needs both specular and diffuse tables");
  tables.alpha = std::stod(store::read_text_attribute(path, "ebrdf/specular/mip1", "alpha"));
  return tables;
}

}  // namespace

PrefilteredTables load_prefiltered_tables(const std::string& path) {
  try {
    return read_tables(path);
  } catch (const RunError& e) {  // a dataset or attribute that is not there
    throw InputError({path}, std::string("is not a readable ebrdf result: ") + e.what());
  } catch (const std::invalid_argument&) {
    throw InputError({path}, "is not a readable ebrdf result: its 'alpha' attribute is not a number");
  }
}

}  // namespace pbrfit::jobs::ebrdf
