# `ebrdf` and `ebrdf_render` results (docs/results-ebrdf.md). ebrdf: the filtered normal map as a picture,
# each component's fit error by mip level (table and plot) and the tables' size; the generic sections then
# show every level's tables. ebrdf_render: each scene's renders side by side (ground truth, naive, ours,
# with their MSE), per scene and distance the MSE, the SSIM and the energy (whole plane and highlight) of
# naive and ours against the ground truth, and plots of the MSE and of the energy ratio over texels per pixel.
import numpy as np

from ... import html_page as page
from ...generic import Renderer, guarded
from ...statistics import number
from .. import register
from .error_figures import energy_figure, level_error_figure, mse_figure
from .render_grid import render_grid


def _figure(report, make, alt, caption):
    name = report.figures.draw(make)
    return [page.image_figure(name, alt, caption)] if name else []


def _levels(file, component):
    group = file[f"ebrdf/{component}"]
    return sorted((int(name[3:]), group[name]) for name in group if name.startswith("mip"))


def _level_rows(file):
    rows, total_bytes = {}, 0
    for component in ("specular", "diffuse"):
        if f"ebrdf/{component}" not in file:
            continue
        for level, g in _levels(file, component):
            error = g["error"][...]
            done = np.isfinite(error)
            rows.setdefault(component, []).append((level, g["matrix"].shape, error[done]))
            total_bytes += g["matrix"].size * 4
    return rows, total_bytes


def _ebrdf_parts(report, file):
    parts = [page.heading(2, "eBRDF prefiltering", "ebrdf")]
    normals = file["ebrdf/normal_map/normal"][...]
    picture = lambda: _normal_picture(normals)
    parts += _figure(report, picture, "normal map", f"ebrdf/normal_map: {normals.shape[0]} x {normals.shape[1]} "
                     f"({file['ebrdf/normal_map'].attrs.get('source', '')}), as RGB = (n + 1) / 2")
    rows, total_bytes = _level_rows(file)
    table_rows = [[c, str(level), f"{shape[0]} x {shape[1]}", f"{shape[2]} x {shape[3]}", str(e.size),
                   number(e.mean()) if e.size else "-", number(np.percentile(e, 95)) if e.size else "-"]
                  for c, levels in rows.items() for level, shape, e in levels]
    parts += [page.table(["component", "level", "texels", "views", "fits", "mean error", "95th percentile"],
                         table_rows, (1, 4, 5, 6)),
              page.paragraph(f"Matrices: {total_bytes / 1e6:.1f} MB of float32 (the thesis' size formula).")]
    parts += _figure(report, lambda: level_error_figure(rows), "error by level",
                     "mean sliced Wasserstein error of the fits by mip level")
    return [page.section(parts)]


def _normal_picture(normals):
    from ...figure_parts import new_figure
    figure = new_figure(3.2, 3.2)
    ax = figure.add_subplot()
    ax.imshow(np.clip((normals + 1) / 2, 0, 1), interpolation="nearest")
    ax.set_xticks([])
    ax.set_yticks([])
    figure.tight_layout(pad=0.2)
    return figure


@register("ebrdf")
class EbrdfRenderer(Renderer):
    def kind_sections(self, report):
        return guarded(lambda: _ebrdf_parts(report, report.file), "ebrdf")


def _ratio(value, truth):
    return number(value / truth) if truth > 0 else "-"


def _render_parts(report, file):
    g = file["ebrdf_render"]
    scenes = g.attrs["scenes"].split(", ")
    distances = g["distance"][...]
    mse, texels = g["mse"][...], g["texels_per_pixel"][...]
    # Results written before the energy and SSIM measures have neither.
    measured = all(name in g for name in ("ssim", "energy", "highlight_energy"))
    parts = [page.heading(2, "Renders: ground truth, naive, prefiltered", "ebrdf_render"),
             page.paragraph(f"{g.attrs.get('shading', '')}. MSE: {g.attrs.get('mse', '')}.")]
    header = ["scene", "distance", "texels per pixel", "naive MSE", "ours MSE", "ours lower"]
    rows = []
    for s in range(len(scenes)):
        for d in range(len(distances)):
            if not np.isfinite(mse[s, d, 0]):
                continue
            row = [scenes[s], number(distances[d]), number(texels[s, d]), number(mse[s, d, 0]), number(mse[s, d, 1]),
                   "yes" if mse[s, d, 1] < mse[s, d, 0] else "no"]
            if measured:
                ssim, energy, highlight = g["ssim"][s, d], g["energy"][s, d], g["highlight_energy"][s, d]
                row += [number(ssim[0]), number(ssim[1]), _ratio(energy[1], energy[0]), _ratio(energy[2], energy[0]),
                        _ratio(highlight[1], highlight[0]), _ratio(highlight[2], highlight[0])]
            rows.append(row)
    if measured:
        header += ["naive SSIM", "ours SSIM", "naive energy / truth", "ours energy / truth",
                   "naive highlight / truth", "ours highlight / truth"]
    parts.append(page.table(header, rows, tuple(i for i in range(1, len(header)) if i != 5)))
    if measured:
        parts.append(page.paragraph("Energy: " + g.attrs.get("energy", "") + "; highlight: " +
                                    g.attrs.get("highlight_energy", "") + ". A ratio of 1 is the ground truth's energy."))
    parts += _figure(report, lambda: mse_figure(scenes, texels, mse), "MSE by texels per pixel",
                     "ebrdf_render/mse over texels per pixel at the image centre")
    if measured:
        energy, highlight = g["energy"][...], g["highlight_energy"][...]
        parts += _figure(report, lambda: energy_figure(scenes, texels, energy, highlight), "energy by texels per pixel",
                         "ebrdf_render/energy and highlight_energy of naive and ours over the ground truth's")
    renders = g["renders"]
    for s, scene in enumerate(scenes):
        parts += _figure(report, lambda s=s: render_grid(renders[s], distances, texels[s], mse[s]), f"{scene} renders",
                         f"ebrdf_render/renders, scene {scene}: a row per distance; ground truth, naive, ours")
    return [page.section(parts)]


@register("ebrdf_render")
class EbrdfRenderRenderer(Renderer):
    def kind_sections(self, report):
        return guarded(lambda: _render_parts(report, report.file), "ebrdf_render")
