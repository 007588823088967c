#pragma once
// What the items of a genBRDF search return (brdf_search_workload.hpp), as bytes and back. Private to the
// brdf jobs. Decoding throws RunError for bytes that do not hold such a record.
#include <span>
#include <vector>

#include "pbrfit/core/error.hpp"
#include "pbrfit/core/item_results.hpp"
#include "pbrfit/jobs/brdf/material_evaluation.hpp"
#include "pbrfit/jobs/brdf/tree_bytes.hpp"

namespace pbrfit::jobs::brdf {

// The log's figures of one island's evaluated generation.
struct IslandStatistics {
  double best_error = gp::worst_error;    // over the finite errors of complete fits
  double median_error = gp::worst_error;  // over every member, abandoned ones at their lower bound
  double median_size = 0.0;
  std::uint32_t infeasible = 0;  // members whose error is not finite
  std::uint32_t abandoned = 0;   // members whose fits were abandoned
};
IslandStatistics island_statistics(std::span<const double> errors, std::span<const double> sizes,
                                   std::span<const std::uint8_t> abandoned);

// A breeding item of an island: the next generation's genomes and their trees, and the statistics of the
// generation they came from.
struct BreedRecord {
  std::vector<gp::Genome> genomes;
  std::vector<gp::SyntaxTree> trees;
  std::uint64_t generation = 0;  // the generation the statistics describe (0 before any evaluation)
  IslandStatistics statistics;
  std::uint32_t migrants_in = 0;
};

// An evaluation item: per tree of its chunk, the error, the tree's size, each material's error and whether
// its fits were abandoned (candidate_score.hpp: the error is then a lower bound).
struct EvaluationRecord {
  std::vector<double> errors, sizes;
  std::vector<std::vector<double>> material_errors;
  std::vector<std::uint8_t> abandoned;
};

// The front item: the Pareto front so far and what entered it at this step.
struct FrontRecord {
  std::vector<ScoredTree> front, additions;
  std::vector<ScoredTree> simplified;            // the last stage only: the knee before and after culling
  std::vector<IslandStatistics> last_generation;  // the last stage only: per island (no breeding logs it)
};

// The averages over a material set of each model's errors, and the reductions of the mean image errors
// relative to the first model (the seed), in per cent.
struct AverageRow {
  std::string set, model;
  double metric_error = 0.0, image_l2 = 0.0, one_minus_ssim = 0.0;
  double l2_reduction = 0.0, ssim_reduction = 0.0;
};

// A kept result the next stage reads; std::logic_error when the runtime did not keep it.
const Bytes& kept_result(const ItemResults& kept, WorkItemId id);

Bytes encode(const BreedRecord& r);
BreedRecord decode_breed(const Bytes& bytes);
Bytes encode(const EvaluationRecord& r);
EvaluationRecord decode_evaluation(const Bytes& bytes);
Bytes encode(const FrontRecord& r);
FrontRecord decode_front(const Bytes& bytes, std::size_t inputs, std::size_t parameters);
Bytes encode(const MaterialEvaluation& r);
MaterialEvaluation decode_material(const Bytes& bytes);
Bytes encode(const std::vector<AverageRow>& rows);
std::vector<AverageRow> decode_averages(const Bytes& bytes);

}  // namespace pbrfit::jobs::brdf
