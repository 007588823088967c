#include "pbrfit/jobs/lut/lut_kind.hpp"

#include "pbrfit/jobs/lut/dfg_table.hpp"
#include "pbrfit/jobs/lut/disney_diffuse_table.hpp"
#include "pbrfit/spec/keys.hpp"

namespace pbrfit::jobs::lut {

namespace {

using brdf::RoughnessParametrization;
using brdf::SmithVisibility;

// What the lut section holds; the DFG-only keys remember whether they were written, since the Disney
// diffuse table refuses them.
struct LutSettings {
  enum class Function { dfg, disney_diffuse } function = Function::dfg;
  spec::Written<SmithVisibility> visibility;
  spec::Written<bool> multiple_scattering, cloth;
  spec::Written<RoughnessParametrization> roughness;
  std::size_t n_dot_v_count = 0, roughness_count = 0;
  Placement placement = Placement::centres;
  integrate::AdaptiveOptions integration;  // per entry
};

spec::Keys<LutSettings> lut_keys() {
  using S = LutSettings;
  spec::Keys<S> k("lut");
  k.choice<S::Function>("function", {{"dfg", S::Function::dfg}, {"disney_diffuse", S::Function::disney_diffuse}},
                        "the table to compute: dfg = split-sum environment BRDF of GGX; disney_diffuse = SH, beta "
                        "and ZH of the Disney diffuse environment lobe",
                        &S::function)
      .require();
  k.choice<SmithVisibility>("visibility",
                            {{"height_correlated", SmithVisibility::height_correlated},
                             {"separable", SmithVisibility::separable},
                             {"separable_schlick", SmithVisibility::separable_schlick}},
                            "Smith masking-shadowing: height_correlated (Filament), separable (exact Smith G1 G1), "
                            "separable_schlick (UE4 / Karis, k = alpha / 2)",
                            &S::visibility)
      .defaults_to(std::string("height_correlated"));
  k.boolean("multiple_scattering", "also tabulate E(n.v) and the Kulla-Conty average albedo per roughness",
            &S::multiple_scattering)
      .defaults_to(false);
  k.boolean("cloth",
            "also tabulate the cloth channel: the albedo of Charlie sheen with Neubelt's visibility, as Filament's "
            "cmgen computes it, alpha from the same roughness axis",
            &S::cloth)
      .defaults_to(false);
  k.choice<RoughnessParametrization>("roughness",
                                     {{"perceptual", RoughnessParametrization::perceptual},
                                      {"linear", RoughnessParametrization::linear},
                                      {"gloss", RoughnessParametrization::gloss}},
                                     "roughness axis: perceptual (alpha = r^2), linear (alpha = r), gloss (alpha = "
                                     "(1 - g)^4, Narkowicz)",
                                     &S::roughness)
      .defaults_to(std::string("perceptual"));
  k.integer_list("resolution", 2, 2, "entries along [n_dot_v, roughness]",
                 [](S& s, const std::vector<std::int64_t>& r) {
                   s.n_dot_v_count = std::size_t(r[0]);
                   s.roughness_count = std::size_t(r[1]);
                 })
      .range(1, 8192)
      .defaults_to(std::vector<std::int64_t>{128, 128});
  k.choice<Placement>("samples", {{"centres", Placement::centres}, {"edges", Placement::edges}},
                      "axis samples at cell centres (i + 0.5) / n or edges i / (n - 1)", &S::placement)
      .defaults_to(std::string("centres"));
  k.number("tolerance", "absolute error allowed per entry",
           [](S& s, double tolerance) { s.integration.abs_tolerance = tolerance; })
      .range(1e-12, 1e-2)
      .defaults_to(1e-6);
  k.integer("max_evaluations", "integrand evaluations allowed per entry before giving up on the tolerance",
            [](S& s, std::int64_t n) { s.integration.max_evaluations = std::size_t(n); })
      .range(1000, 1'000'000'000)
      .defaults_to(std::int64_t{20'000'000});
  // disney_diffuse: the DFG-only keys are refused, so a key never silently does nothing.
  const auto dfg_only = [](auto member) {
    return [member](S& s) -> std::string {
      return s.function == S::Function::disney_diffuse && (s.*member).written ? "applies to function 'dfg' only" : "";
    };
  };
  k.check("visibility", dfg_only(&S::visibility));
  k.check("multiple_scattering", dfg_only(&S::multiple_scattering));
  k.check("roughness", dfg_only(&S::roughness));
  k.check("cloth", dfg_only(&S::cloth));
  k.check("resolution", [](S& s) -> std::string {
    const bool too_few = s.n_dot_v_count < 2 || s.roughness_count < 2;
    return s.placement == Placement::edges && too_few ? "needs at least 2 entries per axis when samples is 'edges'" : "";
  });
  return k;
}

const spec::Keys<LutSettings>& keys() {
  static const spec::Keys<LutSettings> keys = lut_keys();
  return keys;
}

DfgSettings dfg_settings(const LutSettings& lut) {
  DfgSettings s;
  s.visibility = lut.visibility.value;
  s.roughness = lut.roughness.value;
  s.multiple_scattering = lut.multiple_scattering.value;
  s.cloth = lut.cloth.value;
  s.n_dot_v_count = lut.n_dot_v_count;
  s.roughness_count = lut.roughness_count;
  s.placement = lut.placement;
  s.integration = lut.integration;
  return s;
}

DisneyDiffuseSettings disney_settings(const LutSettings& lut) {
  DisneyDiffuseSettings s;
  s.n_dot_v_count = lut.n_dot_v_count;
  s.roughness_count = lut.roughness_count;
  s.placement = lut.placement;
  s.integration = lut.integration;
  return s;
}

std::unique_ptr<runtime::Workload> make_lut(const spec::JobSpec& job) {
  const LutSettings settings = keys().read(job.kind_section);
  if (settings.function == LutSettings::Function::disney_diffuse)
    return std::make_unique<DisneyDiffuseTable>(disney_settings(settings));
  return std::make_unique<DfgTable>(dfg_settings(settings));
}

}  // namespace

JobKind lut_kind() {
  return {"lut", "reference tables by deterministic adaptive integration (function: dfg, disney_diffuse)",
          keys().schema(), make_lut};
}

}  // namespace pbrfit::jobs::lut
