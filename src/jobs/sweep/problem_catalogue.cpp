#include "pbrfit/jobs/sweep/problem_catalogue.hpp"

#include <stdexcept>

#include "pbrfit/core/error.hpp"
#include "pbrfit/jobs/sweep/ltc_ggx_problem.hpp"
#include "pbrfit/store/atomic_file.hpp"

namespace pbrfit::jobs::sweep {
namespace {

std::size_t count_or(const spec::Section& s, const std::string& key, std::size_t fallback) {
  return s.given(key) ? std::size_t(s.get_int(key)) : fallback;
}

// The published table the LTC anchors compare with; null when the data file is not there.
std::shared_ptr<const ltc::PublishedLtcTable> published_ltc_table() {
  const std::string path = std::string(PBRFIT_DATA_DIR) + "/reference/ltc_ggx_heitz2016_64.csv";
  static const std::shared_ptr<const ltc::PublishedLtcTable> table = [&]() -> std::shared_ptr<const ltc::PublishedLtcTable> {
    try {
      const Bytes bytes = store::read_whole_file(path, 4u << 20);
      const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
      return std::make_shared<const ltc::PublishedLtcTable>(ltc::parse_published_ltc_table(text));
    } catch (const InputError&) {
      return nullptr;
    } catch (const std::invalid_argument& e) {
      throw RunError(path + ": " + e.what());
    }
  }();
  return table;
}

std::unique_ptr<SweepProblem> make_ltc(const spec::Section& objective) {
  LtcGgxSettings settings;
  settings.objective_points = count_or(objective, "samples", settings.objective_points);
  settings.metric_points = count_or(objective, "judge_samples", settings.metric_points);
  settings.published = published_ltc_table();
  return make_ltc_ggx_problem(settings);
}

}  // namespace

const std::vector<ProblemEntry>& problem_catalogue() {
  static const std::vector<ProblemEntry> entries = {
      {"ltc_ggx", "isotropic LTC table of GGX (Heitz et al. 2016)", {"samples", "judge_samples"}, make_ltc},
  };
  return entries;
}

std::vector<std::string> problem_names() {
  std::vector<std::string> names;
  for (const auto& entry : problem_catalogue()) names.push_back(entry.name);
  return names;
}

const ProblemEntry& find_problem(const std::string& name) {
  for (const auto& entry : problem_catalogue())
    if (entry.name == name) return entry;
  throw std::logic_error("sweep: unknown problem " + name);
}

spec::Schema objective_schema() {
  spec::Schema s("objective");
  s.integer("samples", "points per sampling strategy of the objective's quasi-Monte Carlo estimate").range(16, 1 << 22);
  s.integer("judge_samples", "points per strategy of the finer estimate the reported errors use").range(16, 1 << 22);
  return s;
}

}  // namespace pbrfit::jobs::sweep
