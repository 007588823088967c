# `ebrdf` and `ebrdf_render` results (docs/results-ebrdf.md). ebrdf: the filtered normal map as a picture,
# each component's fit error by mip level (table and plot) and the tables' size; the generic sections then
# show every level's tables. ebrdf_render: each scene's renders side by side (ground truth, naive, ours,
# with their MSE) and the MSE over texels per pixel.
import numpy as np

from ... import html_page as page
from ...generic import Renderer, guarded
from ...statistics import number
from .. import register
from .error_figures import level_error_figure, mse_figure
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


def _render_parts(report, file):
    g = file["ebrdf_render"]
    scenes = g.attrs["scenes"].split(", ")
    distances = g["distance"][...]
    mse, texels = g["mse"][...], g["texels_per_pixel"][...]
    parts = [page.heading(2, "Renders: ground truth, naive, prefiltered", "ebrdf_render"),
             page.paragraph(f"{g.attrs.get('shading', '')}. MSE: {g.attrs.get('mse', '')}.")]
    rows = [[scenes[s], number(distances[d]), number(texels[s, d]), number(mse[s, d, 0]), number(mse[s, d, 1]),
             "yes" if mse[s, d, 1] < mse[s, d, 0] else "no"]
            for s in range(len(scenes)) for d in range(len(distances)) if np.isfinite(mse[s, d, 0])]
    parts.append(page.table(["scene", "distance", "texels per pixel", "naive MSE", "ours MSE", "ours lower"],
                            rows, (1, 2, 3, 4)))
    parts += _figure(report, lambda: mse_figure(scenes, texels, mse), "MSE by texels per pixel",
                     "ebrdf_render/mse over texels per pixel at the image centre")
    renders = g["renders"]
    for s, scene in enumerate(scenes):
        parts += _figure(report, lambda s=s: render_grid(renders[s], distances, texels[s], mse[s]), f"{scene} renders",
                         f"ebrdf_render/renders, scene {scene}: a row per distance; ground truth, naive, ours")
    return [page.section(parts)]


@register("ebrdf_render")
class EbrdfRenderRenderer(Renderer):
    def kind_sections(self, report):
        return guarded(lambda: _render_parts(report, report.file), "ebrdf_render")
