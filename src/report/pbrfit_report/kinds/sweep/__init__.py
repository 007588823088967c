# `sweep` results (docs/results-sweep.md): first what a reader asks of a fitted table, per model at the
# requested grid (the last level): how large its errors are over the cells (median, 95th percentile,
# worst; relative errors say so in their descriptions), how it compares with a published model cell by
# cell (the ratio map), for GGX LTC tables the fitted lobe beside its target at a few cells, and for other
# sweeps the fitted parameters as curves over the axes; for LTC tables, the check render: a plane under a
# rectangle light lit by the table, by ground truth and by the published table. The generic sections follow
# for every level; vector outputs (a matrix or texture per cell, for engines: `pbrfit export`) are listed
# there but not drawn as slices, and the render's images are only drawn in their own section.
from html import escape

import numpy as np

from ... import html_page as page
from ...anchors import comparisons
from ...attributes import string_attribute
from ...generic import Renderer, guarded
from ...statistics import number
from .. import register
from .check_render import check_render_figure, image_errors, is_render_group, render_images
from .lobe_figure import GGX_MODELS, file_lobe_figure, is_lobes_group, lobe_figure
from .parameter_curves import drawable, parameter_curves_figure
from .ratio_figure import error_ratio, ratio_figure

ERROR_ROLES = ("error",)


def _final_groups(report):
    """The requested grid's groups, and its projections (averages over an axis, attribute projected_over)."""
    return [g for g in report.groups
            if string_attribute(g.node, "final_level") == "true" or string_attribute(g.node, "projected_over")]


def _percentile(values, q):
    finite = values[np.isfinite(values)]
    return float(np.percentile(finite, q)) if finite.size else float("nan")


def _error_rows(group):
    rows = []
    for t in group.tables:
        if t.role not in ERROR_ROLES or t.kind != "grid":
            continue
        values = t.grid_values()[0]
        finite = int(np.count_nonzero(np.isfinite(values)))
        rows.append([t.name, str(finite), number(_percentile(values, 50)), number(_percentile(values, 95)),
                     number(_percentile(values, 100)), t.description])
    return rows


def _comparison_rows(group):
    by_name = {t.name: t for t in group.tables}
    rows = []
    for c in comparisons(group):
        if c.problem or not c.cells:
            continue
        ratio = error_ratio(by_name[c.ours_table].grid_values()[0], by_name[c.anchor_table].grid_values()[0])
        finite = ratio[np.isfinite(ratio)]
        rows.append([c.ours_table, c.anchor, str(c.cells), f"{100 * c.fraction():.1f} %",
                     number(np.median(finite)) if finite.size else "–",
                     number(np.percentile(finite, 95)) if finite.size else "–"])
    return rows


def _figure(report, make, alt, caption):
    name = report.figures.draw(make)
    return [page.image_figure(name, alt, caption)] if name else []


def _lobe_parts(report, group):
    model = string_attribute(group.node, "model")
    computed = [g for g in report.groups if is_lobes_group(g) and string_attribute(g.node, "model") == model]
    if computed and not string_attribute(group.node, "projected_over"):
        return _figure(report, lambda: file_lobe_figure(computed[0]), f"{group.path} lobes",
                       f"{group.path}: the fitted LTC (dashed) beside its target, the BRDF times the cosine (solid), "
                       f"and the published table where there is one (dotted), in the plane of incidence; from "
                       f"{computed[0].path}, each panel scaled to the target's peak")
    by_name = {t.name: t for t in group.tables}
    if model not in GGX_MODELS or "matrix" not in by_name or "norm" not in by_name:
        return []
    matrix_table = by_name["matrix"]
    names = [a.name if a is not None else "" for a in matrix_table.axes]
    if names[:2] != ["sqrt_one_minus_cos", "roughness"]:
        return []
    matrix, norm = matrix_table.grid_values()[0], by_name["norm"].grid_values()[0]
    if any(s != 1 for s in matrix_table.grid_values()[1]):
        return []
    roughness, view_x = matrix_table.axis_values(1), matrix_table.axis_values(0)
    return _figure(report, lambda: lobe_figure(matrix, norm, roughness, view_x), f"{group.path} lobes",
                   f"{group.path}: the fitted LTC (dashed) beside GGX times the cosine (solid) in the plane of "
                   "incidence, each panel scaled to the target's peak")


def _parameter_parts(report, group):
    """The fitted parameters as curves, for sweeps other than LTC tables (whose matrices the lobes show)."""
    if any(t.name == "matrix" for t in group.tables):
        return []
    tables = drawable(group.tables)
    if not tables:
        return []
    return _figure(report, lambda: parameter_curves_figure(tables), f"{group.path} parameters",
                   f"{group.path}: the fitted parameters over the innermost axis, a curve per value of the outer one")


def _group_quality(report, group):
    parts = [page.heading(3, group.path)]
    errors = _error_rows(group)
    if errors:
        parts.append(page.table(["error", "cells", "median", "95th percentile", "worst", "what it measures"],
                                errors, (1, 2, 3, 4)))
    compared = _comparison_rows(group)
    if compared:
        parts.append(page.paragraph("Cell by cell against the published model: the share of cells where ours is "
                                    "at most theirs, and our error over theirs."))
        parts.append(page.table(["ours", "published", "cells", "ours <= theirs", "median ratio",
                                 "95th percentile ratio"], compared, (2, 3, 4, 5)))
        by_name = {t.name: t for t in group.tables}
        for c in comparisons(group):
            if not c.problem and c.cells and by_name[c.ours_table].grid_values()[0].ndim == 2:
                parts += guarded(lambda c=c: _figure(
                    report, lambda: ratio_figure(by_name[c.ours_table], by_name[c.anchor_table], c.anchor),
                    f"{c.ours_table} over {c.anchor_table}",
                    f"{group.path}: {c.ours_table} over {c.anchor_table} per cell (log scale; blue: ours smaller)"),
                    group.path)
    parts += guarded(lambda: _lobe_parts(report, group), group.path)
    parts += guarded(lambda: _parameter_parts(report, group), group.path)
    for table in group.tables:
        table.forget_values()
    return parts


def _render_section(report, group):
    layers, axis = render_images(group)
    if "ltc" not in layers or "reference" not in layers:
        return []
    values = axis.values
    truth = layers["reference"]
    rows = []
    for i, value in enumerate(values):
        ours_mean, ours_p95 = image_errors(layers["ltc"][i], truth[i])
        row = [f"{value:.3g}", f"{100 * ours_mean:.2f} %", f"{100 * ours_p95:.2f} %"]
        if "published" in layers:
            theirs_mean, theirs_p95 = image_errors(layers["published"][i], truth[i])
            row += [f"{100 * theirs_mean:.2f} %", f"{100 * theirs_p95:.2f} %"]
        rows.append(row)
    headers = [axis.name, "this table: mean error", "95th percentile"]
    if "published" in layers:
        headers += ["published: mean error", "95th percentile"]
    model = string_attribute(group.node, "model") or group.path
    parts = [page.heading(3, f"{model}: a plane under a rectangle light"),
             page.paragraph(f"{group.description}. Mean error: the mean of |image - truth| over the mean of the "
                            "truth; 95th percentile: of |image - truth| over the image's brightest truth."),
             page.table(headers, rows, tuple(range(1, len(headers))))]
    parts += _figure(report, lambda: check_render_figure(layers, axis.name, values), f"{group.path} images",
                     f"{group.path}: a row per {axis.name}; the table as a shader reads it, ground truth"
                     + (", the published table" if "published" in layers else "") +
                     ", and the differences from the truth (red: too bright, blue: too dark)")
    return parts


@register("sweep")
class SweepRenderer(Renderer):
    def kind_sections(self, report):
        groups = _final_groups(report)
        if not groups:
            return []
        parts = [page.heading(2, "How good the fit is", "quality"),
                 page.paragraph("Per model at the requested grid (and its averages over an axis, where the job "
                                "asks for them): the errors over its cells, the comparison with "
                                "a published model where the result has one, for GGX tables the fitted lobes, "
                                "for other sweeps the fitted parameters as curves. Every level's tables follow "
                                "below.")]
        for group in groups:
            parts += _group_quality(report, group)
        renders = [g for g in report.groups if is_render_group(g)]
        if renders:
            parts.append(page.heading(2, "How the table lights a plane", "check-render"))
            for group in renders:
                parts += guarded(lambda group=group: _render_section(report, group), group.path)
        return [page.section(parts)]

    def group_section(self, report, group, anchor):
        if is_render_group(group) or is_lobes_group(group):
            layers = page.bullet_list([escape(f"{t.path}: {t.description}") for t in group.tables])
            where = "How the table lights a plane" if is_render_group(group) else "How good the fit is"
            return page.section(self.group_header(group, anchor) + [layers, page.paragraph(
                f"Drawn above, under \"{where}\".", "note")])
        return super().group_section(report, group, anchor)

    def table_figures(self, report, group, table, scale_groups):
        names = [a.name if a is not None else "" for a in table.axes]
        if names and names[-1].endswith("_component"):
            size = table.extent()[-1]
            return [page.paragraph(f"{table.path}: {size} values per cell ({table.description}); not drawn: read "
                                   "them with h5py, or as a texture with pbrfit export", "note")]
        return super().table_figures(report, group, table, scale_groups)
