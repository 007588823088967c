#pragma once
// Settings of the Nelder-Mead simplex method (Pesce & Iwanicki 2015, section 3.2.2). The coefficients
// default to the standard ones: reflection 1, expansion 2, contraction 0.5 (the inside contraction
// x_o - 0.5 (x_o - x_worst) is the course's sigma = -0.5; the outside one is x_o + 0.5 (x_r - x_o)),
// shrink 0.5.
//
// Convergence: the simplex has collapsed when its relative size (largest |vertex - best vertex| / box
// width over vertices and free dimensions) is <= x_tolerance and the spread of its values is
// <= max(f_tolerance_absolute, f_tolerance_relative |best|). A collapse triggers a restart, a fresh
// simplex around the best vertex with restart_step, while restarts remain and the previous restart
// improved the best by more than max(restart_gain_absolute, restart_gain_relative |best|).
#include <cstddef>
#include <limits>
#include <vector>

namespace pbrfit::optimize {

struct NelderMeadOptions {
  double reflection = 1.0;
  double expansion = 2.0;
  double contraction = 0.5;
  double shrink = 0.5;

  double initial_step = 0.1;          // offset of each starting vertex, relative to the box width
  std::vector<double> relative_steps;  // per dimension; overrides initial_step when not empty
  double restart_step = 0.1;          // offset of each vertex of a restart simplex, relative to the width

  double x_tolerance = 1e-9;
  double f_tolerance_absolute = 1e-14;
  double f_tolerance_relative = 1e-10;
  std::size_t max_restarts = 20;
  double restart_gain_absolute = 1e-14;
  double restart_gain_relative = 1e-10;

  std::size_t max_iterations = std::numeric_limits<std::size_t>::max();  // over all restarts
  double target = -std::numeric_limits<double>::infinity();              // stop once best <= target
};

}  // namespace pbrfit::optimize
