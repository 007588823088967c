// The blocks of a genBRDF search's items (brdf_search_workload.hpp): the log row of a breeding item, the
// archive additions of every front item, and the front, its simplified knee and the evaluated models at
// the end.
#include <limits>

#include "pbrfit/jobs/brdf/brdf_inputs.hpp"
#include "pbrfit/jobs/brdf/brdf_search_workload.hpp"
#include "front_knee.hpp"
#include "search_records.hpp"

namespace pbrfit::jobs::brdf {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

void append_log_row(store::Block& log, std::size_t generation, std::size_t island, const IslandStatistics& s,
                    std::uint32_t migrants_in) {
  log.values.insert(log.values.end(), {generation, island, s.best_error, s.median_size, s.infeasible,
                                       s.abandoned, migrants_in});
}

// The log rows of the last generation, which no breeding item describes.
store::Block last_log_block(const FrontRecord& record, std::size_t generation) {
  store::Block log{"brdf", "log", {0}, {record.last_generation.size()}};
  for (std::size_t island = 0; island < record.last_generation.size(); ++island)
    append_log_row(log, generation, island, record.last_generation[island], 0);
  return log;
}

}  // namespace

// The log row of the generation an island bred from (generation 0 breeds from none).
std::vector<store::Block> BrdfSearchWorkload::breed_blocks(const StageItem& at, const BreedRecord& record) const {
  if (at.step == 0) return {};
  store::Block log{"brdf", "log", {0}, {1}};
  append_log_row(log, record.generation, at.item(), record.statistics, record.migrants_in);
  return {log};
}

std::vector<store::Block> BrdfSearchWorkload::front_blocks(const StageItem&, const FrontRecord& record) const {
  std::vector<store::Block> out;
  if (!record.additions.empty()) {
    store::Block archive{"brdf", "archive", {0}, {record.additions.size()}};
    for (const auto& a : record.additions) {
      archive.values.insert(archive.values.end(), {a.size(), a.error, a.generation});
      archive.texts.push_back(expression(a.tree));
    }
    out.push_back(std::move(archive));
  }
  return out;
}

// The archive additions, the last generation's log rows, the front with its knee, the simplified knee and
// the models evaluated.
std::vector<store::Block> BrdfSearchWorkload::last_front_blocks(const StageItem& at, const FrontRecord& record) const {
  std::vector<store::Block> out = front_blocks(at, record);
  if (!record.last_generation.empty()) out.push_back(last_log_block(record, settings_.generations - 1));
  if (record.front.empty()) return out;
  const std::size_t knee = front_knee(record.front);
  store::Block front{"brdf", "front", {0}, {record.front.size()}};
  for (std::size_t k = 0; k < record.front.size(); ++k) {
    const auto& f = record.front[k];
    std::size_t operations = 0, piecewise = 0;
    for (const auto& node : f.tree.nodes()) {
      operations += node.kind == gp::NodeKind::operation;
      piecewise += node.kind == gp::NodeKind::operation && gp::is_piecewise(node.op);
    }
    front.values.insert(front.values.end(), {f.size(), operations, piecewise, f.error, nan, nan, f.generation,
                                             k == knee ? 1u : 0u});
    front.texts.insert(front.texts.end(), {expression(f.tree), ""});
  }
  out.push_back(std::move(front));
  store::Block simplified{"brdf", "simplified", {0}, {record.simplified.size()}};
  for (std::size_t k = 0; k < record.simplified.size(); ++k) {
    simplified.values.insert(simplified.values.end(), {record.simplified[k].size(), record.simplified[k].error});
    simplified.texts.insert(simplified.texts.end(), {k == 0 ? "knee" : "culled", expression(record.simplified[k].tree)});
  }
  if (!record.simplified.empty()) out.push_back(std::move(simplified));
  if (settings_.evaluation.enabled) out.push_back(models_block(record));
  return out;
}

}  // namespace pbrfit::jobs::brdf
