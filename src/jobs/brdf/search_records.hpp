#pragma once
// What the items of a genBRDF search receive and return (brdf_search_workload.hpp), each listing its
// members once for core/serial.hpp. Private to the brdf jobs.
#include <span>
#include <vector>

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
  template <class Archive>
  void serialize(Archive& archive) {
    archive(best_error, median_error, median_size, infeasible, abandoned);
  }
};
IslandStatistics island_statistics(std::span<const double> errors, std::span<const double> sizes,
                                   std::span<const std::uint8_t> abandoned);

// A member of the generation an island breeds from, as its breeding item receives it.
struct Parent {
  gp::Genome genome;
  double error = gp::worst_error;
  double size = 0.0;
  bool abandoned = false;  // the error is a lower bound (candidate_score.hpp)
  template <class Archive>
  void serialize(Archive& archive) {
    archive(genome, error, size, abandoned);
  }
};

// A breeding item's input after generation 0: the island's own members and the migrants that replace its
// worst (none between migrations).
struct BreedInput {
  std::vector<Parent> own, migrants;
  template <class Archive>
  void serialize(Archive& archive) {
    archive(own, migrants);
  }
};

// A breeding item of an island: the next generation's genomes and their trees, and the statistics of the
// generation they came from.
struct BreedRecord {
  std::vector<gp::Genome> genomes;
  std::vector<gp::SyntaxTree> trees;
  std::uint64_t generation = 0;  // the generation the statistics describe (0 before any evaluation)
  IslandStatistics statistics;
  std::uint32_t migrants_in = 0;
  template <class Archive>
  void serialize(Archive& archive) {
    archive(genomes, trees, generation, statistics, migrants_in);
  }
};

// What every evaluation item of a generation reads: the abandon threshold (candidate_score.hpp) and the
// generation's distinct trees, in order of first appearance over the islands' slots.
struct EvaluationContext {
  double abandon_above = gp::worst_error;
  std::vector<gp::SyntaxTree> trees;
  template <class Archive>
  void serialize(Archive& archive) {
    archive(abandon_above, trees);
  }
};

// An evaluation item: per tree of its chunk, the error, the tree's size, each material's error and whether
// its fits were abandoned (candidate_score.hpp: the error is then a lower bound).
struct EvaluationRecord {
  std::vector<double> errors, sizes;
  std::vector<std::vector<double>> material_errors;
  std::vector<std::uint8_t> abandoned;
  template <class Archive>
  void serialize(Archive& archive) {
    archive(errors, sizes, material_errors, abandoned);
  }
};

// The front item: the Pareto front so far and what entered it at this step.
struct FrontRecord {
  std::vector<ScoredTree> front, additions;
  std::vector<ScoredTree> simplified;            // the last stage only: the knee before and after culling
  std::vector<IslandStatistics> last_generation;  // the last stage only: per island (no breeding logs it)
  template <class Archive>
  void serialize(Archive& archive) {
    archive(front, additions, simplified, last_generation);
  }
};

// A front item's input after generation 0: the front before, and every member of the generation just
// evaluated with its abandon flag.
struct FrontInput {
  FrontRecord previous;
  std::vector<ScoredTree> candidates;
  std::vector<std::uint8_t> abandoned;
  template <class Archive>
  void serialize(Archive& archive) {
    archive(previous, candidates, abandoned);
  }
};

// The averages over a material set of each model's errors, and the reductions of the mean image errors
// relative to the first model (the seed), in per cent.
struct AverageRow {
  std::string set, model;
  double metric_error = 0.0, image_l2 = 0.0, one_minus_ssim = 0.0;
  double l2_reduction = 0.0, ssim_reduction = 0.0;
  template <class Archive>
  void serialize(Archive& archive) {
    archive(set, model, metric_error, image_l2, one_minus_ssim, l2_reduction, ssim_reduction);
  }
};

}  // namespace pbrfit::jobs::brdf
