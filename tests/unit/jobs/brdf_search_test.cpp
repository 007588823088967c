// The pieces of the brdf_search kind: the paper's material sets, trees as bytes, the metric as the paper
// defines it (S' = sum of T^2 (f1 - f2)^2 over the kept cells), and the evaluation of one material, on a
// material tabulated from Cook-Torrance with known parameters.
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <set>

#include "pbrfit/brdf/merl_tabulation.hpp"
#include "pbrfit/core/bytes.hpp"
#include "pbrfit/gp/expression_parser.hpp"
#include "pbrfit/gp/pareto.hpp"
#include "pbrfit/jobs/brdf/analytic_brdf.hpp"
#include "pbrfit/jobs/brdf/brdf_inputs.hpp"
#include "pbrfit/jobs/brdf/candidate_score.hpp"
#include "pbrfit/jobs/brdf/material_evaluation.hpp"
#include "pbrfit/jobs/brdf/material_sets.hpp"
#include "pbrfit/jobs/brdf/seed_brdfs.hpp"
#include "pbrfit/jobs/brdf/tree_bytes.hpp"
#include "pbrfit/render/procedural_environments.hpp"
#include "front_knee.hpp"  // private to the brdf jobs (src/jobs/brdf)

using namespace pbrfit;
using namespace pbrfit::jobs::brdf;

namespace {

gp::SyntaxTree tree_of_text(const std::string& text) {
  const auto p = std::get<gp::ParsedExpression>(gp::parse_expression(text, {pbrfit::brdf::direction_input_names(), brdf_parameter_names()}));
  return gp::tree_of(p.program, p.parameter_slots);
}

gp::CompiledTree compiled(const gp::SyntaxTree& tree) { return *gp::compile(tree, brdf_parameter_count); }

const gp::SyntaxTree& cook_torrance() {
  static const auto tree = tree_of_text(find_seed("cook_torrance")->expression);
  return tree;
}

// Per channel: diffuse, specular, roughness, R0.
const std::vector<std::vector<double>> known = {{0.05, 1.0, 0.3, 0.5}, {0.03, 0.8, 0.3, 0.5}, {0.02, 0.6, 0.3, 0.5}};

const brdf::MerlTable& cook_torrance_material() {
  static const auto table = brdf::tabulate_on_merl_grid(analytic_brdf(compiled(cook_torrance()), known));
  return table;
}

const BrdfScene& small_scene() {
  static const auto scene = [] {
    render::SphereSamples samples(render::procedural_interior(), render::SphereView(32), 4);
    render::PrunedLightTable table{render::LightWeightTable(samples)};
    return BrdfScene{std::move(samples), std::move(table), {}};
  }();
  return scene;
}

}  // namespace

TEST_CASE("the paper's found BRDFs evaluate as its equations 6 and 7 print them") {
  const double pi = 3.141592653589793;
  const std::vector<double> p = {0.2, 0.7, 0.4, 0.3};  // k'_d, k'_s, alpha, beta
  const double kd = p[0], ks = p[1], alpha = p[2], beta = p[3];
  const auto metal = analytic_brdf(compiled(tree_of_text(find_seed("brady_metal")->expression)), {p, p, p});
  const auto dielectric = analytic_brdf(compiled(tree_of_text(find_seed("brady_dielectric")->expression)), {p, p, p});
  for (const auto& [l, v] : {std::pair{Vector3(0.3, 0.1, 0.9), Vector3(-0.2, 0.3, 0.8)},
                             std::pair{Vector3(0.7, 0.0, 0.4), Vector3(-0.6, 0.2, 0.5)}}) {
    const Vector3 wi = l.normalized(), wo = v.normalized(), h = (wi + wo).normalized();
    const double nl = wi.z(), nv = wo.z(), nh = h.z(), vh = wo.dot(h), delta = std::acos(nh);
    const double metal_expected = kd / pi + ks * std::exp(-delta / beta) *
                                                std::min(alpha / kd * vh, 4 * beta / (std::tan(delta) * nv * nl)) *
                                                (alpha + std::pow(1 - vh, 5));
    const double f = alpha + (1 - alpha) * std::pow(1 - nh, 5);
    const double d = std::exp(-std::pow(std::tan(delta) / beta, 2)) / (beta * beta * std::pow(std::cos(delta), 4));
    const double dielectric_expected =
        kd * std::pow(1 + std::cos(delta), 1 - alpha) +
        std::min(1 / std::sqrt(kd), f * d / (pi * vh * nl * nv)) * std::exp(-std::tan(delta) / ks) /
            (alpha * alpha * (alpha + 2) * beta);
    CHECK(std::abs(metal(wi, wo)[0] - metal_expected) < 1e-12 * metal_expected);
    CHECK(std::abs(dielectric(wi, wo)[1] - dielectric_expected) < 1e-12 * dielectric_expected);
  }
}

TEST_CASE("the paper's material sets: 4 training and 16 testing MERL materials each, disjoint") {
  const std::set<std::string> merl(merl_material_names().begin(), merl_material_names().end());
  CHECK(merl.size() == 100);
  std::set<std::string> all;
  for (const auto* name : {"metals", "dielectrics"}) {
    const auto set = material_set(name);
    REQUIRE(set);
    CHECK(set->training.size() == 4);
    CHECK(set->testing.size() == 16);
    for (const auto* list : {&set->training, &set->testing})
      for (const auto& m : *list) {
        INFO(m);
        CHECK(merl.contains(m));
        CHECK(all.insert(m).second);  // in no other list
      }
  }
  CHECK_FALSE(material_set("plastics"));
}

TEST_CASE("trees read back from bytes as written; damaged bytes are refused") {
  ByteWriter out;
  write_tree(out, cook_torrance());
  const Bytes bytes = out.bytes();
  ByteReader in(bytes);
  CHECK(read_tree(in, brdf_input_count, brdf_parameter_count) == cook_torrance());
  for (std::size_t cut : {std::size_t{1}, bytes.size() / 2, bytes.size() - 1}) {
    const Bytes shorter(bytes.begin(), bytes.begin() + std::ptrdiff_t(cut));
    ByteReader damaged(shorter);
    CHECK_THROWS_AS(read_tree(damaged, brdf_input_count, brdf_parameter_count), ByteFormatError);
  }
  ByteReader fewer_inputs(bytes);
  CHECK_THROWS_AS(read_tree(fewer_inputs, 2, brdf_parameter_count), ByteFormatError);
}

TEST_CASE("the metric of a fitted constant is the T^2-weighted spread of the material about its weighted mean") {
  const MetricData data(small_scene().table, {cook_torrance_material()}, {"ct"});
  const auto score = score_candidate(compiled(tree_of_text("p0")), data, {3, 200}, RandomStream(1, 0));
  double expected = 0.0;
  for (std::size_t c = 0; c < 3; ++c) {
    const auto& d = data.channel(0, c).data;
    const double mean = (d.weights * d.target).sum() / d.weights.sum();
    expected += (d.weights * (d.target - mean).square()).sum();
  }
  CHECK(std::abs(score.error * score.error - expected) < 1e-3 * expected);
  CHECK(score.material_errors.size() == 1);
}

TEST_CASE("Cook-Torrance fits a material made from Cook-Torrance far better than a constant does") {
  const MetricData data(small_scene().table, {cook_torrance_material()}, {"ct"});
  const auto fit = score_candidate(compiled(cook_torrance()), data, {8, 400}, RandomStream(2, 0));
  const auto constant = score_candidate(compiled(tree_of_text("p0")), data, {3, 200}, RandomStream(2, 0));
  CHECK(fit.error < 0.05 * constant.error);
  const auto again = score_candidate(compiled(cook_torrance()), data, {8, 400}, RandomStream(2, 0));
  CHECK(again.error == fit.error);  // deterministic
  CHECK(again.parameters == fit.parameters);
}

TEST_CASE("each fit's first search starts from the fit before it, unless warm starts are off") {
  const MetricData data(small_scene().table, {cook_torrance_material(), cook_torrance_material()}, {"a", "b"});
  gp::ParameterFitOptions one_evaluation{1, 1};  // each search evaluates its start only
  const auto warm = score_candidate(compiled(tree_of_text("p0 * nl")), data, one_evaluation, RandomStream(3, 0));
  REQUIRE(warm.parameters.size() == 6);
  for (std::size_t k = 1; k < 6; ++k) CHECK(warm.parameters[k] == warm.parameters[0]);
  one_evaluation.warm_start = false;
  const auto cold = score_candidate(compiled(tree_of_text("p0 * nl")), data, one_evaluation, RandomStream(3, 0));
  CHECK(cold.parameters[0] == warm.parameters[0]);  // the first fit has no fit before it
  CHECK(cold.parameters[1] != cold.parameters[0]);
}

TEST_CASE("the knee of a search's front is a BRDF, not the fitted constant at its cheap end") {
  // Shaped like a real metal front: a parameter-free tree, a fitted constant, then slowly better BRDFs.
  const std::vector<std::pair<const char*, double>> members = {
      {"1", 799.0}, {"p0 + 1", 64.0}, {"p0 * nl + p1", 50.0}, {"p0 * pow(nh, p1) + p2", 30.0},
      {"p0 * pow(nh, p1) + p2 * nl", 15.0}, {"(p0 * pow(nh, p1) + p2 * nl) / (nl + nv + p3)", 10.0}};
  std::vector<ScoredTree> front;
  std::vector<gp::Fitness> fitness;
  for (const auto& [text, error] : members) {
    front.push_back({tree_of_text(text), error, 0});
    fitness.push_back({error, front.back().size(), 0.0, true});
  }
  for (std::size_t k = 1; k < front.size(); ++k) REQUIRE(front[k].size() > front[k - 1].size());
  CHECK(gp::knee_index(fitness) == 1);  // over the whole front the constant p0 + 1 is the knee
  CHECK(front_knee(front) == 4);        // over the members that beat it: the 9-node BRDF
  SECTION("a front without input-free members is taken whole") {
    const std::span<const ScoredTree> real = std::span(front).subspan(2);
    CHECK(front_knee(real) == gp::knee_index(std::span(fitness).subspan(2)));
  }
  SECTION("so is a front of constants only") {
    CHECK(front_knee(std::span(front).first(2)) == gp::knee_index(std::span(fitness).first(2)));
  }
}

TEST_CASE("evaluating a material renders it measured and fitted, and compares the renders") {
  const std::vector<gp::SyntaxTree> models = {cook_torrance(), tree_of_text("p0")};
  const auto result = evaluate_on_material(small_scene(), small_scene(), cook_torrance_material(), "ct", models,
                                           {8, 400}, 1.0, RandomStream(3, 0));
  REQUIRE(result.models.size() == 2);
  CHECK(result.renders.size() == 3 * 32 * 32 * 3);
  const auto& ct = result.models[0];
  const auto& flat = result.models[1];
  CHECK(ct.image_l2 < 0.3 * flat.image_l2);
  CHECK(ct.one_minus_ssim < flat.one_minus_ssim);
  CHECK(ct.parameters.size() == 3 * brdf_parameter_count);
  // The measured render and Cook-Torrance's are not black.
  CHECK(std::any_of(result.renders.begin(), result.renders.begin() + 32 * 32 * 3, [](auto v) { return v > 20; }));
}

TEST_CASE("a candidate worse than the threshold on its first materials is abandoned with a lower bound") {
  const MetricData data(small_scene().table, {cook_torrance_material(), cook_torrance_material(), cook_torrance_material()},
                        {"a", "b", "c"});
  const auto constant = compiled(tree_of_text("p0"));
  const auto full = score_candidate(constant, data, {3, 200}, RandomStream(4, 0));
  REQUIRE_FALSE(full.abandoned);
  REQUIRE(full.material_errors.size() == 3);
  SECTION("above the threshold after the first material: the others are skipped") {
    const auto cut = score_candidate(constant, data, {3, 200}, RandomStream(4, 0), 0.5 * full.material_errors[0]);
    CHECK(cut.abandoned);
    CHECK(cut.material_errors.size() == 1);
    CHECK(cut.error == full.material_errors[0]);
    CHECK(cut.error < full.error);  // a lower bound
    CHECK(cut.evaluations < full.evaluations / 2);
  }
  SECTION("a threshold the full error stays under changes nothing") {
    const auto kept = score_candidate(constant, data, {3, 200}, RandomStream(4, 0), 1.01 * full.error);
    CHECK_FALSE(kept.abandoned);
    CHECK(kept.error == full.error);
    CHECK(kept.parameters == full.parameters);
  }
  SECTION("exceeding it only with the last material is no reason to stop: the error is complete") {
    const double before_last = std::hypot(full.material_errors[0], full.material_errors[1]);
    const auto last = score_candidate(constant, data, {3, 200}, RandomStream(4, 0), 0.5 * (before_last + full.error));
    CHECK_FALSE(last.abandoned);
    CHECK(last.error == full.error);
  }
}

TEST_CASE("a candidate without a finite error on its first material is not fitted further") {
  const MetricData data(small_scene().table, {cook_torrance_material(), cook_torrance_material()}, {"a", "b"});
  const auto infinite = score_candidate(compiled(tree_of_text("p0 / (nl - nl)")), data, {2, 50}, RandomStream(5, 0));
  CHECK(infinite.error == gp::worst_error);
  CHECK(infinite.material_errors.size() == 1);
}
