#include "pbrfit/jobs/table_export.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <numeric>

#include "pbrfit/core/error.hpp"
#include "pbrfit/core/quoted_text.hpp"

namespace pbrfit::jobs {
namespace {

using Dims = std::vector<std::uint64_t>;

std::string listed(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

[[noreturn]] void refuse(const std::string& where, const std::string& message) { throw InputError({where}, message); }

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

// One numeric table of the result with its axis names.
struct Table {
  std::vector<double> values;
  Dims dims;
  std::vector<std::string> axes;
};

Table read(const std::string& path, const std::string& dataset) {
  Table t;
  t.values = store::read_table(path, dataset, &t.dims);
  try {
    t.axes = store::read_name_list_attribute(path, dataset, "axes");
  } catch (const RunError&) {
  }
  if (t.axes.size() != t.dims.size()) {
    t.axes.clear();
    for (std::size_t d = 0; d < t.dims.size(); ++d) t.axes.push_back("axis" + std::to_string(d));
  }
  return t;
}

// A table's grid (its axes without a trailing component axis) as the texture's axes, fastest last.
struct Grid {
  std::vector<std::string> axes;  // outermost first
  Dims dims;
  std::size_t components = 1;     // values per grid point
};

bool is_component_axis(const std::string& name) { return name.size() > 10 && name.ends_with("_component"); }

Grid grid_of(const Table& t) {
  Grid g{t.axes, t.dims, 1};
  if (!g.axes.empty() && is_component_axis(g.axes.back())) {
    g.components = std::size_t(g.dims.back());
    g.axes.pop_back();
    g.dims.pop_back();
  }
  return g;
}

// Channel planes over one grid: planes[c][point].
struct Planes {
  Grid grid;
  std::vector<std::string> names;
  std::vector<std::vector<double>> planes;
};

// The LTC textures' components by what they hold (docs/results-sweep.md); others by index: "matrix.4".
std::string component_name(const std::string& table, std::size_t c) {
  static const char* ltc_1[] = {"m00", "m20", "m02", "m22"};
  static const char* ltc_2[] = {"norm", "fresnel", "zero", "sphere"};
  if ((table == "ltc_1" || table == "published_ltc_1") && c < 4) return ltc_1[c];
  if ((table == "ltc_2" || table == "published_ltc_2") && c < 4) return ltc_2[c];
  return table + "." + std::to_string(c);
}

void add_planes(Planes& out, const Table& t, const std::string& name, const std::string& where) {
  const Grid g = grid_of(t);
  if (out.names.empty()) out.grid = {g.axes, g.dims, 1};
  if (g.dims != out.grid.dims) refuse(where, "table '" + name + "' does not share the grid of the others");
  const std::size_t points = t.values.size() / g.components;
  for (std::size_t c = 0; c < g.components; ++c) {
    std::vector<double> plane(points);
    for (std::size_t i = 0; i < points; ++i) plane[i] = t.values[i * g.components + c];
    out.planes.push_back(std::move(plane));
    out.names.push_back(g.components == 1 ? name : component_name(name, c));
  }
}

// The requested channels (by name), or the defaults.
Planes select(Planes all, const std::vector<std::string>& requested, const std::vector<std::string>& defaults) {
  const auto& names = requested.empty() ? defaults : requested;
  Planes out{all.grid, {}, {}};
  for (const auto& name : names) {
    const auto found = std::ranges::find(all.names, name);
    if (found == all.names.end())
      refuse("--channels", "names '" + name + "', which this table does not have (it has: " + listed(all.names) + ")");
    out.names.push_back(name);
    out.planes.push_back(all.planes[std::size_t(found - all.names.begin())]);
  }
  if (out.names.empty() || out.names.size() > 4) refuse("--channels", "picks " + std::to_string(out.names.size()) +
                                                                          " channels; a texture holds 1 to 4");
  return out;
}

// The texture of planes over a grid of 1 to 3 axes (last axis along u), optionally transposed and flipped.
texture::Texture texture_of(const Planes& p, const TableRequest& request, const std::string& path) {
  Grid grid = p.grid;
  if (grid.dims.empty() || grid.dims.size() > 3)
    refuse(path, "table '" + request.table + "' has " + std::to_string(grid.dims.size()) +
                     " grid axes; a texture holds 1 to 3");
  std::vector<std::size_t> order(grid.dims.size());  // texture axis k (outermost first) reads grid axis order[k]
  std::iota(order.begin(), order.end(), 0);
  if (!request.u_axis.empty()) {
    const auto found = std::ranges::find(grid.axes, request.u_axis);
    if (grid.dims.size() != 2 || found == grid.axes.end())
      refuse("--u-axis", "is '" + request.u_axis + "'; this table's axes are " + listed(grid.axes) +
                             (grid.dims.size() == 2 ? "" : " (only a 2D table can swap them)"));
    if (found == grid.axes.begin()) order = {1, 0};
  }
  texture::Texture t;
  const std::size_t n = order.size();
  const auto extent = [&](std::size_t k) { return std::size_t(grid.dims[order[k]]); };
  t.width = extent(n - 1);
  t.height = n >= 2 ? extent(n - 2) : 1;
  t.depth = n >= 3 ? extent(0) : 1;
  t.channels = p.names;
  t.values.resize(t.width * t.height * t.depth * p.names.size());
  std::vector<std::size_t> stride(grid.dims.size(), 1);
  for (std::size_t d = grid.dims.size() - 1; d-- > 0;) stride[d] = stride[d + 1] * std::size_t(grid.dims[d + 1]);
  for (std::size_t z = 0; z < t.depth; ++z)
    for (std::size_t y = 0; y < t.height; ++y)
      for (std::size_t x = 0; x < t.width; ++x) {
        const std::size_t row = request.flip_v ? t.height - 1 - y : y;
        std::size_t index = x * stride[order[n - 1]];
        if (n >= 2) index += row * stride[order[n - 2]];
        if (n >= 3) index += z * stride[order[0]];
        for (std::size_t c = 0; c < p.names.size(); ++c)
          t.values[((z * t.height + y) * t.width + x) * p.names.size() + c] = p.planes[c][index];
      }
  const char* roles[] = {"u", "v", "w"};
  for (std::size_t k = 0; k < n; ++k) t.metadata.push_back({std::string("axis_") + roles[k], grid.axes[order[n - 1 - k]]});
  if (request.flip_v) t.metadata.push_back({"rows", "flipped: the first row is the last value of the v axis"});
  return t;
}

// Axis values: first, last, count, written as metadata so a shader can map a parameter to a texel.
void describe_axes(texture::Texture& t, const std::string& path, const std::string& group) {
  std::vector<std::pair<std::string, std::string>> extra;
  for (const auto& [key, axis] : t.metadata) {
    if (!key.starts_with("axis_")) continue;
    try {
      const auto values = store::read_table(path, group + "/" + axis);
      if (!values.empty())
        extra.push_back({key + "_values", "first " + number(values.front()) + ", last " + number(values.back()) +
                                              ", count " + std::to_string(values.size()) + " (texel centres)"});
    } catch (const RunError&) {
    }
  }
  t.metadata.insert(t.metadata.end(), extra.begin(), extra.end());
}

void describe_source(texture::Texture& t, const std::string& path, const store::ResultSummary& s, const std::string& what) {
  t.name = what;
  t.metadata.insert(t.metadata.begin(), {{"source", path}, {"job", s.job_name}, {"kind", s.job_kind}, {"table", what}});
  std::string channels;
  for (const auto& c : t.channels) channels += (channels.empty() ? "" : ", ") + c;
  t.metadata.push_back({"channel_meaning", channels});
}

bool has_dataset(const std::string& path, const std::string& group, const std::string& name) {
  try {
    const auto names = store::read_dataset_names(path, group);
    return std::ranges::find(names, name) != names.end();
  } catch (const RunError&) {
    return false;
  }
}

// --- lut --------------------------------------------------------------------------------------------------
texture::Texture lut_texture(const std::string& path, const store::ResultSummary& s, TableRequest request) {
  const bool dfg = has_dataset(path, "dfg", "scale");
  const std::string group = dfg ? "dfg" : "disney_diffuse";
  const std::string main = group;
  if (request.table.empty()) request.table = main;
  if (request.table != main) refuse("--table", "is '" + request.table + "'; this result holds the table '" + main + "'");
  Planes all;
  std::vector<std::string> defaults;
  const std::vector<std::string> candidates =
      dfg ? std::vector<std::string>{"scale", "bias", "energy", "cloth"}
          : std::vector<std::string>{"beta", "zh0", "zh1", "zh2", "zh1_ratio", "zh2_ratio"};
  for (const auto& name : candidates)
    if (has_dataset(path, group, name)) add_planes(all, read(path, group + "/" + name), name, path);
  defaults = dfg ? std::vector<std::string>{"scale", "bias"} : std::vector<std::string>{"beta", "zh0", "zh1_ratio", "zh2_ratio"};
  if (dfg && has_dataset(path, group, "cloth")) defaults.push_back("cloth");
  texture::Texture t = texture_of(select(all, request.channels, defaults), request, path);
  describe_axes(t, path, group);
  describe_source(t, path, s, main);
  return t;
}

// --- sweep ------------------------------------------------------------------------------------------------
std::string final_level(const std::string& path, const std::string& model) {
  for (const auto& level : store::read_group_names(path, model)) {
    try {
      if (store::read_text_attribute(path, model + "/" + level, "final_level") == "true") return model + "/" + level;
    } catch (const RunError&) {
    }
  }
  refuse(path, "model '" + model + "' has no final level");
}

std::string chosen_model(const std::string& path, const std::string& requested) {
  const auto models = store::read_group_names(path, "");
  if (requested.empty()) {
    if (models.size() == 1) return models.front();
    refuse("--model", "is needed: this sweep holds the models " + listed(models));
  }
  if (std::ranges::find(models, requested) == models.end())
    refuse("--model", "is '" + requested + "', not a model of this sweep (" + listed(models) + ")");
  return requested;
}

std::vector<std::string> model_parameters(const std::string& path, const std::string& group) {
  // The parameters are the tables whose role is `parameter`.
  std::vector<std::string> out;
  for (const auto& name : store::read_dataset_names(path, group)) {
    try {
      if (store::read_text_attribute(path, group + "/" + name, "role") == "parameter") out.push_back(name);
    } catch (const RunError&) {
    }
  }
  return out;
}

std::vector<std::string> sweep_tables(const std::string& path, const std::string& group) {
  std::vector<std::string> out;
  const auto names = store::read_dataset_names(path, group);
  const bool ltc = std::ranges::find(names, "ltc_1") != names.end();
  if (ltc) out.push_back("ltc");
  out.push_back("parameters");
  for (const auto& name : names) {
    try {
      store::read_text_attribute(path, group + "/" + name, "role");
      out.push_back(name);
    } catch (const RunError&) {  // axes have no role
    }
  }
  return out;
}

texture::Texture ltc_pair(const std::string& path, const store::ResultSummary& s, const std::string& group,
                          TableRequest request) {
  if (!request.channels.empty()) refuse("--channels", "does not apply to table 'ltc' (ltc_1 and ltc_2 as they are)");
  if (!request.u_axis.empty()) refuse("--u-axis", "does not apply to table 'ltc' (roughness runs along u)");
  const Table one = read(path, group + "/ltc_1"), two = read(path, group + "/ltc_2");
  Planes p1, p2;
  add_planes(p1, one, "ltc_1", path);
  add_planes(p2, two, "ltc_2", path);
  // Every outer slice (an expression's added axes) gives two layers: its ltc_1, then its ltc_2.
  Grid inner = p1.grid;
  std::size_t slices = 1;
  while (inner.dims.size() > 2) slices *= std::size_t(inner.dims.front()), inner.dims.erase(inner.dims.begin()), inner.axes.erase(inner.axes.begin());
  const std::size_t points = p1.planes[0].size() / slices;
  texture::Texture t;
  bool first = true;
  for (std::size_t slice = 0; slice < slices; ++slice) {
    for (const Planes* p : {&p1, &p2}) {
      Planes part{inner, {"r", "g", "b", "a"}, {}};
      for (const auto& plane : p->planes)
        part.planes.emplace_back(plane.begin() + std::ptrdiff_t(slice * points), plane.begin() + std::ptrdiff_t((slice + 1) * points));
      TableRequest layer = request;
      layer.table = "ltc";
      texture::Texture piece = texture_of(part, layer, path);
      if (first) {
        t = piece;
        first = false;
      } else {
        t.values.insert(t.values.end(), piece.values.begin(), piece.values.end());
        ++t.layers;
      }
    }
  }
  t.metadata.push_back({"layers", "ltc_1 then ltc_2" + std::string(slices > 1 ? " for each slice of the outer axes" : "")});
  describe_axes(t, path, group);
  describe_source(t, path, s, group + "/ltc");
  return t;
}

texture::Texture sweep_texture(const std::string& path, const store::ResultSummary& s, TableRequest request) {
  const std::string model = chosen_model(path, request.model);
  const std::string group = final_level(path, model);
  const auto tables = sweep_tables(path, group);
  if (request.table.empty()) request.table = tables.front();
  if (std::ranges::find(tables, request.table) == tables.end())
    refuse("--table", "is '" + request.table + "', not a table of " + group + " (" + listed(tables) + ")");
  if (request.table == "ltc") return ltc_pair(path, s, group, request);
  Planes all;
  std::vector<std::string> defaults;
  if (request.table == "parameters") {
    for (const auto& name : model_parameters(path, group)) add_planes(all, read(path, group + "/" + name), name, path);
    defaults = all.names;
    if (defaults.size() > 4 && request.channels.empty())
      refuse("--channels", "is needed: model '" + model + "' has " + std::to_string(defaults.size()) +
                               " parameters (" + listed(defaults) + "); pick at most 4");
  } else {
    add_planes(all, read(path, group + "/" + request.table), request.table, path);
    defaults = all.names;
    if (defaults.size() > 4 && request.channels.empty())
      refuse("--channels", "is needed: table '" + request.table + "' has " + std::to_string(defaults.size()) +
                               " components; pick at most 4 (" + request.table + ".0, ...)");
  }
  texture::Texture t = texture_of(select(all, request.channels, defaults), request, path);
  describe_axes(t, path, group);
  describe_source(t, path, s, group + "/" + request.table);
  return t;
}

// --- ebrdf ------------------------------------------------------------------------------------------------
texture::Texture ebrdf_texture(const std::string& path, const store::ResultSummary& s, TableRequest request) {
  if (request.table.empty()) request.table = "specular";
  const auto components = store::read_group_names(path, "ebrdf");
  std::vector<std::string> offered;
  for (const auto& c : components)
    if (c != "normal_map") offered.push_back(c);
  if (std::ranges::find(offered, request.table) == offered.end())
    refuse("--table", "is '" + request.table + "', not a component of this eBRDF result (" + listed(offered) + ")");
  if (!request.channels.empty() || !request.u_axis.empty() || request.flip_v)
    refuse(request.channels.empty() ? (request.u_axis.empty() ? "--flip-v" : "--u-axis") : "--channels",
           "does not apply to an eBRDF mip hierarchy (its layout is fixed: docs/export.md)");
  const std::string base = "ebrdf/" + request.table;
  std::vector<std::string> levels = store::read_group_names(path, base);
  std::sort(levels.begin(), levels.end(), [](const std::string& a, const std::string& b) {
    return std::stoul(a.substr(3)) < std::stoul(b.substr(3));
  });
  texture::Texture t;
  t.channels = {"r", "g", "b", "a"};
  t.levels = levels.size();
  std::size_t views = 0;
  for (std::size_t l = 0; l < levels.size(); ++l) {
    const std::string group = base + "/" + levels[l];
    const Table m = read(path, group + "/matrix"), a = read(path, group + "/amplitude"), e = read(path, group + "/error");
    if (m.dims.size() != 5 || m.dims[4] != 9) refuse(path, group + "/matrix is not [v][u][theta][phi][9]");
    const std::size_t rows = m.dims[0], cols = m.dims[1], level_views = m.dims[2] * m.dims[3];
    if (l == 0) {
      t.width = cols, t.height = rows, views = level_views, t.layers = 3 * views;
      t.metadata.push_back({"views", std::to_string(m.dims[2]) + " theta x " + std::to_string(m.dims[3]) + " phi, theta-major"});
    }
    if (level_views != views || cols != std::max<std::size_t>(1, t.width >> l) || rows != std::max<std::size_t>(1, t.height >> l))
      refuse(path, base + " is not a mip chain halving from " + std::to_string(t.width) + " x " + std::to_string(t.height));
    for (std::size_t view = 0; view < views; ++view)
      for (std::size_t slice = 0; slice < 3; ++slice)
        for (std::size_t y = 0; y < rows; ++y)
          for (std::size_t x = 0; x < cols; ++x) {
            const std::size_t point = (y * cols + x) * views + view;
            for (std::size_t c = 0; c < 4; ++c) {
              const std::size_t k = 4 * slice + c;
              t.values.push_back(k < 9 ? m.values[point * 9 + k] : k == 9 ? a.values[point] : k == 10 ? e.values[point] : 0.0);
            }
          }
  }
  t.metadata.push_back({"layers", "3 per view: (m00, m01, m02, m10), (m11, m12, m20, m21), (m22, amplitude, error, 0) "
                                  "of the row-major M"});
  describe_source(t, path, s, base);
  return t;
}

std::vector<std::string> exportable_tables_of(const std::string& path, const store::ResultSummary& s, const std::string& model) {
  if (s.job_kind == "lut") return {has_dataset(path, "dfg", "scale") ? "dfg" : "disney_diffuse"};
  if (s.job_kind == "sweep") return sweep_tables(path, final_level(path, chosen_model(path, model)));
  if (s.job_kind == "ebrdf") {
    std::vector<std::string> out;
    for (const auto& c : store::read_group_names(path, "ebrdf"))
      if (c != "normal_map") out.push_back(c);
    return out;
  }
  return {};
}

texture::Texture table_texture_of(const std::string& path, const store::ResultSummary& s, const TableRequest& request) {
  if (s.state != store::RunStatus::complete)
    refuse(path, "is " + quote(store::run_status_name(s.state)) + ", not complete: export its tables once the job has finished");
  if (s.job_kind == "lut") return lut_texture(path, s, request);
  if (s.job_kind == "sweep") return sweep_texture(path, s, request);
  if (s.job_kind == "ebrdf") return ebrdf_texture(path, s, request);
  refuse(path, "is a '" + s.job_kind + "' result, which holds no tables to export as textures (lut, sweep and ebrdf "
               "results do; a symreg or brdf_search front member exports as a function with --format hlsl, glsl or cpp)");
}

// A result file whose tables cannot be read (damaged after its summary attributes) is the user's input:
// refused naming it, as a file that does not open is.
template <class Read>
auto reading(const std::string& path, Read&& read) {
  try {
    return read();
  } catch (const RunError& e) {
    refuse(path, std::string("is damaged: ") + e.what());
  }
}

}  // namespace

std::vector<std::string> exportable_tables(const std::string& path, const store::ResultSummary& s, const std::string& model) {
  return reading(path, [&] { return exportable_tables_of(path, s, model); });
}

texture::Texture table_texture(const std::string& path, const store::ResultSummary& s, const TableRequest& request) {
  return reading(path, [&] { return table_texture_of(path, s, request); });
}

}  // namespace pbrfit::jobs
