#include "pbrfit/ebrdf/procedural_normal_maps.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "pbrfit/core/random_stream.hpp"

namespace pbrfit::ebrdf {
namespace {


// Feature points of a periodic Worley grid: one per cell of a cells x cells grid over the unit torus.
struct PointGrid {
  std::size_t cells;
  std::vector<std::array<double, 2>> points;

  PointGrid(std::size_t cell_count, RandomStream random) : cells(cell_count), points(cell_count * cell_count) {
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double u = random.uniform(), v = random.uniform();
      points[i] = {(double(i % cells) + u) / double(cells), (double(i / cells) + v) / double(cells)};
    }
  }

  // The two smallest torus distances from (x, y) to feature points, and the index of the nearest.
  struct Nearest {
    double first = 1e9, second = 1e9;
    std::size_t index = 0;
  };
  Nearest nearest(double x, double y) const {
    Nearest result;
    const auto cx = static_cast<std::int64_t>(x * double(cells)), cy = static_cast<std::int64_t>(y * double(cells));
    const auto n = static_cast<std::int64_t>(cells);
    for (std::int64_t dy = -2; dy <= 2; ++dy)
      for (std::int64_t dx = -2; dx <= 2; ++dx) {
        const std::size_t i = std::size_t(((cx + dx) % n + n) % n) + std::size_t(((cy + dy) % n + n) % n) * cells;
        double ex = std::abs(points[i][0] - x), ey = std::abs(points[i][1] - y);
        ex = std::min(ex, 1.0 - ex);
        ey = std::min(ey, 1.0 - ey);
        const double d = std::hypot(ex, ey);
        if (d < result.first) {
          result.second = result.first;
          result = {d, result.second, i};
        } else if (d < result.second) {
          result.second = d;
        }
      }
    return result;
  }
};

// Periodic value noise with `period` lattice cells over the unit torus, smoothly interpolated, in [0, 1).
double value_noise(double x, double y, std::size_t period, std::uint64_t seed) {
  const double fx = x * double(period), fy = y * double(period);
  const auto ix = static_cast<std::uint64_t>(std::floor(fx)), iy = static_cast<std::uint64_t>(std::floor(fy));
  const double tx = fx - std::floor(fx), ty = fy - std::floor(fy);
  const auto lattice = [&](std::uint64_t i, std::uint64_t j) {
    return RandomStream(seed, (i % period) + (j % period) * period).uniform();
  };
  const auto smooth = [](double t) { return t * t * (3.0 - 2.0 * t); };
  const double sx = smooth(tx), sy = smooth(ty);
  const double top = lattice(ix, iy) * (1 - sx) + lattice(ix + 1, iy) * sx;
  const double bottom = lattice(ix, iy + 1) * (1 - sx) + lattice(ix + 1, iy + 1) * sx;
  return top * (1 - sy) + bottom * sy;
}

std::vector<double> stone_heights(std::size_t size, std::uint64_t seed) {
  const std::size_t cells = std::clamp<std::size_t>(size / 16, 2, 64);
  const PointGrid grid(cells, RandomStream(seed, 1));
  std::vector<double> heights(size * size);
  for (std::size_t y = 0; y < size; ++y)
    for (std::size_t x = 0; x < size; ++x) {
      const double u = (double(x) + 0.5) / double(size), v = (double(y) + 0.5) / double(size);
      const auto nearest = grid.nearest(u, v);
      const double edge = std::min(1.0, (nearest.second - nearest.first) * double(cells) * 2.5);
      double detail = 0.0, amplitude = 0.5;
      for (std::size_t octave = 0, period = 4; octave < 4 && period <= size; ++octave, period *= 2) {
        detail += amplitude * value_noise(u, v, period, seed + 100 + octave);
        amplitude *= 0.5;
      }
      heights[x + y * size] = (std::sqrt(edge) * 0.06 + detail * 0.02);
    }
  return heights;
}

NormalMap glitter_map(std::size_t size, std::uint64_t seed) {
  const std::size_t cells = std::max<std::size_t>(1, size / 3);
  const PointGrid grid(cells, RandomStream(seed, 2));
  const double max_tilt = 35.0 * std::numbers::pi / 180.0;
  std::vector<Vector3> normals(size * size);
  for (std::size_t y = 0; y < size; ++y)
    for (std::size_t x = 0; x < size; ++x) {
      const auto nearest = grid.nearest((double(x) + 0.5) / double(size), (double(y) + 0.5) / double(size));
      RandomStream facet(seed, 3, nearest.index);
      const double tilt = max_tilt * std::sqrt(facet.uniform());
      const double azimuth = 2.0 * std::numbers::pi * facet.uniform();
      normals[x + y * size] = {std::sin(tilt) * std::cos(azimuth), std::sin(tilt) * std::sin(azimuth), std::cos(tilt)};
    }
  return NormalMap(size, std::move(normals));
}

// Grooves along lines through random points with random directions; a line wraps around the torus by
// being tested against the nearest periodic copy of its point.
std::vector<double> scratch_heights(std::size_t size, std::uint64_t seed) {
  RandomStream random(seed, 4);
  const std::size_t count = 6 + size / 16;
  std::vector<double> heights(size * size, 0.0);
  const double width = 1.5 / double(size);
  for (std::size_t s = 0; s < count; ++s) {
    const double px = random.uniform(), py = random.uniform();
    // Directions with rational slopes keep a wrapped line periodic: (a, b) small integers.
    const int a = 1 + int(random.below(3)), b = int(random.below(7)) - 3;
    const bool swap = random.below(2) == 1;
    const double dx = swap ? b : a, dy = swap ? a : b;
    const double length = std::hypot(dx, dy);
    const double depth = 0.004 * (0.5 + random.uniform());
    for (std::size_t y = 0; y < size; ++y)
      for (std::size_t x = 0; x < size; ++x) {
        double ex = (double(x) + 0.5) / double(size) - px, ey = (double(y) + 0.5) / double(size) - py;
        // Distance to the line on the torus: the smallest over nearby periodic copies.
        double distance = 1e9;
        for (int ox = -3; ox <= 3; ++ox)
          for (int oy = -3; oy <= 3; ++oy)
            distance = std::min(distance, std::abs((ex + ox) * dy - (ey + oy) * dx) / length);
        if (distance < width) heights[x + y * size] -= depth * (1.0 - distance / width);
      }
  }
  return heights;
}

}  // namespace

const std::vector<std::string>& normal_pattern_names() {
  static const std::vector<std::string> names = {"stone", "glitter", "scratches"};
  return names;
}

NormalPattern normal_pattern_from(const std::string& name) {
  if (name == "stone") return NormalPattern::stone;
  if (name == "glitter") return NormalPattern::glitter;
  if (name == "scratches") return NormalPattern::scratches;
  throw std::invalid_argument("ebrdf: unknown normal map pattern " + name);
}

NormalMap normals_from_heights(std::size_t size, const std::vector<double>& heights) {
  std::vector<Vector3> normals(size * size);
  const auto h = [&](std::size_t x, std::size_t y) { return heights[(x % size) + (y % size) * size]; };
  const double scale = double(size) / 2.0;
  for (std::size_t y = 0; y < size; ++y)
    for (std::size_t x = 0; x < size; ++x) {
      const double dx = (h(x + 1, y) - h(x + size - 1, y)) * scale;
      const double dy = (h(x, y + 1) - h(x, y + size - 1)) * scale;
      normals[x + y * size] = Vector3(-dx, -dy, 1.0).normalized();
    }
  return NormalMap(size, std::move(normals));
}

NormalMap procedural_normal_map(NormalPattern pattern, std::size_t size, std::uint64_t seed) {
  if (!is_power_of_two(size) || size > 4096) throw std::invalid_argument("ebrdf: map size must be a power of two");
  switch (pattern) {
    case NormalPattern::stone: return normals_from_heights(size, stone_heights(size, seed));
    case NormalPattern::glitter: return glitter_map(size, seed);
    case NormalPattern::scratches: return normals_from_heights(size, scratch_heights(size, seed));
  }
  throw std::logic_error("unhandled normal pattern");
}

}  // namespace pbrfit::ebrdf
