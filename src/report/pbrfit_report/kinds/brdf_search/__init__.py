# `brdf_search` results (docs/results-brdf_search.md): the paper's tables first - each model's mean image
# L2 and 1 - SSIM on the training and testing materials with the reductions against Cook-Torrance - then
# the evaluated models, their BRDFs for people (simplified by SymPy with integers and pi exact, typeset;
# the exact text a click away: readable_expressions.py), the renders side by side (measured, Cook-Torrance,
# found), the front over tree size, and the remaining record tables. A job whose evaluation has not run yet
# says so.
import numpy as np

from ... import html_page as page
from ...attributes import string_attribute
from ...formula_figure import formula_figure
from ...generic import Renderer, guarded
from ...readable_expressions import latex, plain
from ...statistics import number
from .. import register
from .front_figure import brdf_front_figure
from .render_grid import MAX_ROWS, render_grid

SHOWN_HERE = {"/brdf": {"front"}, "/brdf/evaluation": {"averages", "models", "renders", "materials"}}


def _texts(records, field):
    return [v.decode() if isinstance(v, bytes) else str(v) for v in records[field]]


def _figure(report, make, alt, caption):
    name = report.figures.draw(make)
    return [page.image_figure(name, alt, caption)] if name else []


def _averages_markup(averages):
    rows = [[s, m, number(r["metric_error"]), number(r["image_l2"]), number(r["one_minus_ssim"]),
             f"{r['l2_reduction']:.1f} %", f"{r['ssim_reduction']:.1f} %"]
            for s, m, r in zip(_texts(averages, "set"), _texts(averages, "model"), averages)]
    header = ["materials", "model", "mean metric error", "mean image L2", "mean 1 - SSIM", "L2 reduction",
              "1 - SSIM reduction"]
    return page.table(header, rows, (2, 3, 4, 5, 6))


def _inputs(file):
    return [name.strip() for name in string_attribute(file["brdf"], "inputs").split(",") if name.strip()]


def _models_markup(models, inputs):
    rows = [[m, number(r["cost"]), number(r["training_error"]), page.with_exact_text(plain(e, inputs), e)]
            for m, e, r in zip(_texts(models, "model"), _texts(models, "expression"), models)]
    return page.table(["model", "size", "search error", "BRDF (simplified; the exact text a click away)"], rows,
                      (1, 2))


def _formula_parts(report, models, inputs):
    """Each evaluated model's BRDF typeset, where SymPy and mathtext can lay it out on one line."""
    parts = []
    for name, text in zip(_texts(models, "model"), _texts(models, "expression")):
        formula = guarded(lambda text=text: [latex(text, inputs, exact_constants=True)], name)[0]
        if not isinstance(formula, str):
            continue
        made = report.figures.draw(lambda formula=formula: formula_figure(formula))
        if made:
            parts.append(page.image_figure(made, f"{name} formula", f"{name}: f(l, v) = the BRDF above, typeset"))
    return parts


def _render_parts(report, evaluation):
    materials = evaluation.attrs["materials"].split(", ")
    images = evaluation.attrs["images"].split(", ")
    rows = evaluation["materials"][()]
    errors = {}
    for k, r in enumerate(rows):
        errors[(k // (len(images) - 1), k % (len(images) - 1) + 1)] = (r["image_l2"], r["one_minus_ssim"])
    renders = evaluation["renders"]
    shown = min(len(materials), MAX_ROWS, renders.shape[0])
    left_out = "" if shown == len(materials) else f"; the first {shown} of {len(materials)} materials"
    caption = (f"brdf/evaluation/renders: each material measured and under each fitted model{left_out} "
               f"({evaluation.attrs.get('render', '')}; {evaluation.attrs.get('display', '')})")
    return _figure(report, lambda: render_grid(renders[:shown], materials[:shown], images, errors),
                   "brdf/evaluation/renders", caption)


def _evaluation_parts(report, file):
    if "brdf/evaluation" not in file or len(file["brdf/evaluation/averages"]) == 0:
        return [page.paragraph("No evaluation yet: it runs after the last generation (or is disabled in the job).")]
    evaluation = file["brdf/evaluation"]
    parts = [page.heading(3, "brdf/evaluation/averages: mean errors over each material set"),
             _averages_markup(evaluation["averages"][()]),
             page.heading(3, "brdf/evaluation/models")]
    models, inputs = evaluation["models"][()], _inputs(file)
    parts.append(_models_markup(models, inputs))
    parts += guarded(lambda: _formula_parts(report, models, inputs), "brdf/evaluation/models")
    return parts + guarded(lambda: _render_parts(report, evaluation), "brdf/evaluation/renders")


def _front_parts(report, file):
    front = file["brdf/front"][()] if "brdf/front" in file else []
    if len(front) == 0:
        return [page.paragraph("No front yet: the job has not finished its last generation.")]
    models = file["brdf/evaluation/models"][()] if "brdf/evaluation/models" in file else []
    seed_size = models[0]["cost"] if len(models) else None  # the seed is the first model evaluated
    return _figure(report, lambda: brdf_front_figure(front, seed_size), "brdf/front",
                   f"brdf/front: {len(front)} members; the knee ringed")


@register("brdf_search")
class BrdfSearchRenderer(Renderer):
    def kind_sections(self, report):
        parts = [page.heading(2, "genBRDF search", "brdf_search")]
        parts += guarded(lambda: _evaluation_parts(report, report.file), "brdf/evaluation")
        parts += guarded(lambda: _front_parts(report, report.file), "brdf/front")
        return [page.section(parts)]

    def group_section(self, report, group, anchor):
        hidden = SHOWN_HERE.get(group.path)
        if hidden is None:
            return super().group_section(report, group, anchor)
        parts = self.group_header(group, anchor)
        for table in (t for t in group.tables if t.name not in hidden and t.kind == "rows"):
            parts += self.rows_section(table)
        return page.section(parts)
