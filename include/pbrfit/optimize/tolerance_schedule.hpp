#pragma once
// Cooperative accuracy (Pesce & Iwanicki 2015, section 3.2.1): the objective is evaluated coarsely while
// the optimizer explores and tightly once it has narrowed down on a minimum.
//
// The optimizers measure how far they have narrowed the search as a relative scale: the extent of the DE
// population, or of the Nelder-Mead simplex, divided by the box width, largest over the dimensions (1 =
// the whole box). at(scale) maps it to a tolerance:
//  - scale >= 1 gives `start`; scale <= final_scale gives `final`;
//  - in between, the tolerance steps geometrically through `levels` values from start to final, each
//    reached when log(scale) / log(final_scale) passes its fraction of the way;
//  - at() is non-increasing in scale whenever final <= start. The evaluator only ever tightens, so the
//    tolerance an objective sees within one run never grows.
// start == final (the default) is a constant tolerance: optimizers then never spend evaluations on
// re-measuring at a tighter one.
namespace pbrfit::optimize {

struct ToleranceSchedule {
  double start = 1e-6;        // tolerance while the search spans the whole box
  double final = 1e-6;        // tolerance of the polish and of every reported best value
  double final_scale = 1e-3;  // relative search scale at which `final` is reached
  int levels = 4;             // distinct tolerances from start to final, both included (at least 2)

  static ToleranceSchedule constant(double tolerance) { return {tolerance, tolerance, 1e-3, 2}; }

  bool is_constant() const { return start == final; }
  double at(double relative_scale) const;
};

}  // namespace pbrfit::optimize
