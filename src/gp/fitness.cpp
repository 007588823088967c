#include "pbrfit/gp/fitness.hpp"

namespace pbrfit::gp {
namespace {

// An unevaluated fitness ranks below every evaluated one.
double ranked(const Fitness& f, std::size_t k) { return f.evaluated ? f.objective(k) : worst_error; }

}  // namespace

bool dominates(const Fitness& a, const Fitness& b, std::size_t objective_count) {
  bool better_somewhere = false;
  for (std::size_t k = 0; k < objective_count; ++k) {
    const double x = ranked(a, k);
    const double y = ranked(b, k);
    if (x > y) return false;
    better_somewhere = better_somewhere || x < y;
  }
  return better_somewhere;
}

bool same_objectives(const Fitness& a, const Fitness& b, std::size_t objective_count) {
  for (std::size_t k = 0; k < objective_count; ++k) {
    if (ranked(a, k) != ranked(b, k)) return false;
  }
  return true;
}

}  // namespace pbrfit::gp
