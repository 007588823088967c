#include "pbrfit/jobs/lut/disney_diffuse_table.hpp"

#include <cmath>
#include <cstdio>
#include <map>

#include "pbrfit/brdf/disney_diffuse_course_fit.hpp"
#include "pbrfit/brdf/disney_diffuse_lobe.hpp"
#include "pbrfit/core/error.hpp"

namespace pbrfit::jobs::lut {
namespace {

// Offsets of an entry's values (values_per_entry of them).
enum Value : std::size_t { sh0 = 0, dir_x = 9, dir_z = 10, beta = 11, zh0 = 12, zh1 = 13, zh2 = 14, estimate = 15 };

double ratio(double a, double b) { return b != 0.0 ? a / b : std::nan(""); }

}  // namespace

DisneyDiffuseTable::DisneyDiffuseTable(const DisneyDiffuseSettings& settings)
    : settings_(settings),
      n_dot_v_(unit_axis(settings.n_dot_v_count, settings.placement)),
      roughness_(unit_axis(settings.roughness_count, settings.placement)) {
  add_stage(runtime::stage<Nothing, Nothing, Row>("rows", 1, this)
                .items(&DisneyDiffuseTable::row_count)
                .compute(&DisneyDiffuseTable::compute_row)
                .check(&DisneyDiffuseTable::check_row)
                .blocks(&DisneyDiffuseTable::row_blocks)
                .fold(&DisneyDiffuseTable::fold_row));
}

store::ResultLayout DisneyDiffuseTable::layout() const {
  store::Group g;
  g.name = "disney_diffuse";
  g.description = "Disney diffuse environment lobe (baseColor 1, cosine-weighted), projected onto 3rd-order SH; "
                  "lobe axis d = normalize((1 - beta) n + beta v), ZH about d (Pesce & Iwanicki 2015, section 6)";
  g.attributes = {{"function", "disney_diffuse"},
                  {"sh_convention", "real SH bands 0-2, orthonormal, no Condon-Shortley phase, index l*l + l + m"},
                  {"tolerance", std::to_string(settings_.integration.abs_tolerance)},
                  {"course_fits", "section 6.4 of the course notes as printed; their ZH0 has another normalization "
                                  "or sign convention (it is negative), so compare the ratios and beta"}};
  g.axes = {{"roughness", roughness_, "Disney roughness in [0, 1]"},
            {"n_dot_v", n_dot_v_, "cosine between normal and view"},
            {"sh_index", {0, 1, 2, 3, 4, 5, 6, 7, 8}, "SH index l*l + l + m"}};
  const std::vector<std::string> grid = {"roughness", "n_dot_v"};
  const auto table = [&](const char* name, const char* description, const char* role = "output") {
    store::Table t{name, grid, description};
    t.attributes = {{"role", role}};
    return t;
  };
  g.tables = {{"sh", {"roughness", "n_dot_v", "sh_index"}, "SH coefficients of the lobe"},
              table("beta", "blend factor of the optimal linear direction between n and v"),
              table("zh0", "zonal coefficient of band 0 about the lobe axis"),
              table("zh1", "zonal coefficient of band 1 about the lobe axis"),
              table("zh2", "zonal coefficient of band 2 about the lobe axis"),
              table("zh1_ratio", "ZH1 / ZH0"),
              table("zh2_ratio", "ZH2 / ZH0"),
              table("error_estimate", "absolute error estimate of the SH integrals", "error"),
              table("course_beta", "the course's fit of beta"),
              table("course_zh0", "the course's fit of ZH0, as printed"),
              table("course_zh1_ratio", "the course's linear fit of ZH1 / ZH0"),
              table("course_zh2_ratio", "the course's linear fit of ZH2 / ZH0"),
              table("course_beta_deviation", "|course beta - beta|", "error"),
              table("course_zh1_ratio_deviation", "|course ZH1/ZH0 - ZH1/ZH0|", "error"),
              table("course_zh2_ratio_deviation", "|course ZH2/ZH0 - ZH2/ZH0|", "error"),
              table("constant_zh1_ratio_deviation", "|1.1564 - ZH1/ZH0| (the course's constant form)", "error"),
              table("constant_zh2_ratio_deviation", "|0.5634 - ZH2/ZH0| (the course's constant form)", "error")};
  return {{g}};
}

DisneyDiffuseTable::Row DisneyDiffuseTable::compute_row(const runtime::StageTask<Nothing, Nothing>& task) const {
  const double r = roughness_[task.item()];
  std::vector<double> row;
  for (double mu : n_dot_v_) {
    const auto lobe = brdf::disney_diffuse_lobe(r, mu, settings_.integration);
    if (!lobe.converged) {
      char text[240];
      std::snprintf(text, sizeof text, "entry (n_dot_v %.3g, roughness %.3g) did not reach the tolerance %.3g "
                    "(error estimate %.3g); raise max_evaluations or the tolerance", mu, r,
                    settings_.integration.abs_tolerance, lobe.error_estimate);
      throw RunError(text);
    }
    row.insert(row.end(), lobe.sh.begin(), lobe.sh.end());
    row.insert(row.end(), {lobe.direction.x(), lobe.direction.z(), lobe.beta, lobe.zh[0], lobe.zh[1], lobe.zh[2],
                           lobe.error_estimate});
    if (task.stop_requested()) throw runtime::Cancelled();
  }
  return row;
}

void DisneyDiffuseTable::check_row(const runtime::StageItem&, const Row& row) const {
  if (row.size() != n_dot_v_.size() * values_per_entry) throw RunError("Disney diffuse row result has the wrong length");
}

std::vector<store::Block> DisneyDiffuseTable::row_blocks(const runtime::StageItem& at, const Row& row) const {
  const WorkItemId id = at.id;
  const std::uint64_t n = n_dot_v_.size();
  const double r = roughness_[id.item];
  std::map<std::string, std::vector<double>> columns;
  std::vector<double> sh;
  for (std::size_t i = 0; i < n; ++i) {
    const double* e = row.data() + i * values_per_entry;
    const double mu = n_dot_v_[i];
    sh.insert(sh.end(), e + sh0, e + sh0 + 9);
    const double zh1_ratio = ratio(e[zh1], e[zh0]), zh2_ratio = ratio(e[zh2], e[zh0]);
    columns["beta"].push_back(e[beta]);
    columns["zh0"].push_back(e[zh0]);
    columns["zh1"].push_back(e[zh1]);
    columns["zh2"].push_back(e[zh2]);
    columns["zh1_ratio"].push_back(zh1_ratio);
    columns["zh2_ratio"].push_back(zh2_ratio);
    columns["error_estimate"].push_back(e[estimate]);
    columns["course_beta"].push_back(brdf::course_disney_beta(r, mu));
    columns["course_zh0"].push_back(brdf::course_disney_zh0(r, mu));
    columns["course_zh1_ratio"].push_back(brdf::course_disney_zh1_ratio(r, mu));
    columns["course_zh2_ratio"].push_back(brdf::course_disney_zh2_ratio(r, mu));
    columns["course_beta_deviation"].push_back(std::abs(brdf::course_disney_beta(r, mu) - e[beta]));
    columns["course_zh1_ratio_deviation"].push_back(std::abs(brdf::course_disney_zh1_ratio(r, mu) - zh1_ratio));
    columns["course_zh2_ratio_deviation"].push_back(std::abs(brdf::course_disney_zh2_ratio(r, mu) - zh2_ratio));
    columns["constant_zh1_ratio_deviation"].push_back(std::abs(brdf::course_disney_zh1_constant_ratio - zh1_ratio));
    columns["constant_zh2_ratio_deviation"].push_back(std::abs(brdf::course_disney_zh2_constant_ratio - zh2_ratio));
  }
  std::vector<store::Block> out = {{"disney_diffuse", "sh", {id.item, 0, 0}, {1, n, 9}, store::reals(sh)}};
  for (const auto& [name, values] : columns) out.push_back({"disney_diffuse", name, {id.item, 0}, {1, n}, store::reals(values)});
  return out;
}

void DisneyDiffuseTable::fold_row(Summary& sum, const runtime::StageItem& at, const Row& row) const {
  for (std::size_t i = 0; i < n_dot_v_.size(); ++i) {
    const double* e = row.data() + i * values_per_entry;
    sum.worst_estimate = std::max(sum.worst_estimate, e[estimate]);
    const double deviation = std::abs(brdf::course_disney_beta(roughness_[at.item()], n_dot_v_[i]) - e[beta]);
    sum.worst_beta_deviation = std::max(sum.worst_beta_deviation, deviation);
    ++sum.entries;
  }
}

std::string DisneyDiffuseTable::headline_of(const Summary& sum) const {
  if (sum.entries == 0) return "no entries yet";
  char text[200];
  std::snprintf(text, sizeof text, "%llu entries, max error estimate %.2g, largest |course beta - beta| %.3g",
                static_cast<unsigned long long>(sum.entries), sum.worst_estimate, sum.worst_beta_deviation);
  return text;
}

}  // namespace pbrfit::jobs::lut
