#include "pbrfit/ebrdf/mip_tables.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace pbrfit::ebrdf {
namespace {

// The two grid points around a continuous index and the weight of the upper one.
struct Bracket {
  std::size_t low, high;
  double t;
};

Bracket wrapped(double position, std::size_t n) {
  const double f = std::floor(position);
  const auto i = static_cast<std::int64_t>(f);
  const auto side = static_cast<std::int64_t>(n);
  const auto wrap = [side](std::int64_t k) { return std::size_t(((k % side) + side) % side); };
  return {wrap(i), wrap(i + 1), position - f};
}

Bracket clamped(double position, std::size_t n) {
  const double p = std::clamp(position, 0.0, double(n - 1));
  const auto low = std::min(n - 1, static_cast<std::size_t>(p));
  return {low, std::min(n - 1, low + 1), p - double(low)};
}

Bracket theta_bracket(const ViewGrid& views, double theta) {
  if (views.n_theta == 1) return {0, 0, 0.0};
  return clamped(views.theta_position(theta), views.n_theta);
}

// The turn about y that takes z to the mirror direction (-sin theta, 0, cos theta) of the view at
// elevation theta and azimuth 0.
Matrix3 mirror_frame(double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  Matrix3 r;
  r << c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c;
  return r;
}

}  // namespace

LtcMipTables::LtcMipTables(ViewGrid views, std::vector<LtcLevel> levels, LobeAxis axis)
    : views_(views), levels_(std::move(levels)), axis_(axis) {
  if (levels_.empty()) throw std::invalid_argument("ebrdf: an LTC mip hierarchy needs at least one level");
  for (const auto& level : levels_) {
    const std::size_t entries = level.side * level.side * views_.count();
    if (level.matrices.size() != 9 * entries || level.amplitudes.size() != entries)
      throw std::invalid_argument("ebrdf: an LTC level's tables do not match its size and views");
  }
}

void LtcMipTables::accumulate_views(const LtcLevel& table, std::size_t texel, double theta, double phi, double weight,
                                    LtcLookup& sum) const {
  const Bracket t = theta_bracket(views_, theta);
  const Bracket p = wrapped(phi / (2.0 * std::numbers::pi) * double(views_.n_phi), views_.n_phi);
  // The tabulated views' mirror frames (identity for a lobe about the normal).
  const Matrix3 low_frame = axis_ == LobeAxis::mirror ? Matrix3(mirror_frame(views_.theta(t.low)).transpose()) : Matrix3(Matrix3::Identity());
  const Matrix3 high_frame = axis_ == LobeAxis::mirror ? Matrix3(mirror_frame(views_.theta(t.high)).transpose()) : Matrix3(Matrix3::Identity());
  for (int corner = 0; corner < 4; ++corner) {
    const double w = weight * ((corner & 1) ? t.t : 1 - t.t) * ((corner & 2) ? p.t : 1 - p.t);
    if (w == 0.0) continue;
    const std::size_t view = ((corner & 1) ? t.high : t.low) * views_.n_phi + ((corner & 2) ? p.high : p.low);
    const std::size_t entry = texel * views_.count() + view;
    const float* m = table.matrices.data() + 9 * entry;
    Matrix3 matrix;
    for (int k = 0; k < 9; ++k) matrix(k / 3, k % 3) = m[k];
    sum.matrix += w * ((corner & 1) ? high_frame : low_frame) * matrix;
    sum.amplitude += w * table.amplitudes[entry];
  }
}

std::vector<WeightedLtc> LtcMipTables::texel_lobes(double level, double u, double v, double theta,
                                                   double phi) const {
  const double l = std::clamp(level, 1.0, double(levels_.size()));
  const auto low = std::min(levels_.size(), static_cast<std::size_t>(l));
  const double t = l - double(low);
  const Matrix3 turn = axis_ == LobeAxis::mirror ? mirror_frame(theta) : Matrix3(Matrix3::Identity());
  std::vector<WeightedLtc> lobes;
  for (std::size_t k = 0; k < 2; ++k) {
    const std::size_t index = low - 1 + k;
    const double level_weight = k == 0 ? 1.0 - t : t;
    if (level_weight == 0.0 || index >= levels_.size()) continue;
    const LtcLevel& table = levels_[index];
    const Bracket x = wrapped(u * double(table.side) - 0.5, table.side);
    const Bracket y = wrapped(v * double(table.side) - 0.5, table.side);
    for (int corner = 0; corner < 4; ++corner) {
      const double w = level_weight * ((corner & 1) ? x.t : 1 - x.t) * ((corner & 2) ? y.t : 1 - y.t);
      if (w == 0.0) continue;
      const std::size_t texel = ((corner & 2) ? y.high : y.low) * table.side + ((corner & 1) ? x.high : x.low);
      LtcLookup lobe;
      lobe.matrix.setZero();
      accumulate_views(table, texel, theta, phi, 1.0, lobe);
      lobe.matrix = turn * lobe.matrix;
      lobes.push_back({w, lobe});
    }
  }
  return lobes;
}

LtcLookup LtcMipTables::lookup(double level, double u, double v, double theta, double phi) const {
  LtcLookup sum;
  sum.matrix.setZero();
  for (const WeightedLtc& texel : texel_lobes(level, u, v, theta, phi)) {
    sum.matrix += texel.weight * texel.lobe.matrix;
    sum.amplitude += texel.weight * texel.lobe.amplitude;
  }
  return sum;
}

}  // namespace pbrfit::ebrdf
