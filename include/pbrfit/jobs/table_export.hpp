#pragma once
// The tables of a result that an engine samples, as textures (`pbrfit export RESULT --table NAME --format F`,
// docs/export.md): what each kind's result offers, and the texture a request makes of it.
//
// Tables, by kind (u is the texture's fast axis, x; v its rows, y; rows in the file's order unless flipped):
//   lut dfg             `dfg`: channels scale, bias, then cloth when the result has it (cmgen's RG and B;
//                       energy on request); u = n_dot_v, v = the roughness axis
//   lut disney_diffuse  `disney_diffuse`: beta, zh0, zh1_ratio, zh2_ratio (zh1, zh2 on request); u = n_dot_v
//   sweep               per model (the result's groups; --model when there are several), its final level:
//                       every table of the level by name (a vector table's components are its channels, at
//                       most 4), `parameters` (the model's fitted parameters as channels), and for LTC tables
//                       `ltc_1`, `ltc_2` and `ltc` (both, as a 2-layer array: ltc_1 then ltc_2). The last grid
//                       axis is u, the one before v, a third (an expression's added axis, a sphere light's
//                       incidence) is the depth of a volume, or, for `ltc`, further layers (each slice's
//                       ltc_1 and ltc_2). LTC tables: u = roughness, v = sqrt(1 - cos theta_v), as the
//                       reference shaders and three.js sample them.
//   ebrdf               `specular`, `diffuse`: every mip level as a mip level of a texture array whose layers
//                       are (view, slice) with view = theta-major over (theta, phi) and 3 slices per view:
//                       (m00, m01, m02, m10), (m11, m12, m20, m21), (m22, amplitude, error, 0) of the row-major
//                       M; u, v the map's texel axes.
// A request may pick and order channels by name (`channels`), swap u and v of a 2D table (`u_axis` names the
// axis to run along u) and flip the rows (`flip_v`). The texture's metadata records the source file, job,
// table, its axes (name, first and last value, count, and whether values sit at texel edges or centres) and
// what each channel is.
//
// Refusals are InputErrors naming the result file or the option: a result that is not complete; a kind
// without tables; an unknown table, model or channel (listing the valid ones); a table of more than 3 grid
// axes; a u_axis that is not one of a 2D table's axes.
#include <string>
#include <vector>

#include "pbrfit/store/result_file.hpp"
#include "pbrfit/texture/texture.hpp"

namespace pbrfit::jobs {

struct TableRequest {
  std::string table;                  // empty: the kind's main table (dfg, disney_diffuse, ltc, specular)
  std::string model;                  // sweep: the model (group); empty: the only one
  std::vector<std::string> channels;  // empty: the table's default channels
  std::string u_axis;                 // empty: the default
  bool flip_v = false;
};

// The tables a request could name for this result (for a sweep: of the chosen or only model).
std::vector<std::string> exportable_tables(const std::string& path, const store::ResultSummary& summary,
                                           const std::string& model = {});

texture::Texture table_texture(const std::string& path, const store::ResultSummary& summary,
                               const TableRequest& request);

}  // namespace pbrfit::jobs
