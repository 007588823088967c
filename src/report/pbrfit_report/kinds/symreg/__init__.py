# `symreg` results (docs/results-symreg.md): an overview of the outputs' knees, then per output group its
# knee typeset, its front (error vs cost with members labelled, the knee ringed, the anchors as stars;
# expressions with their constants rounded, readable.py), the front and
# anchors tables side by side (each anchor beside our best member at equal or lower cost), the knee's
# residuals over the inputs, the islands' best error over the generations and the archive's first rows;
# the group `subexpressions` as the table of recurring sub-expressions. Other groups get the generic
# section. A job still running has no front yet: the page says so and shows the log so far.
import numpy as np

from ... import html_page as page
from ...formula_figure import formula_figure
from ...generic import Renderer, guarded
from ...readable_expressions import latex
from ...statistics import number
from .. import register
from .front_figure import front_figure
from .front_tables import anchors_markup, front_markup, recurring_markup
from .log_figure import log_figure
from .output_tables import is_output_group, read_output, texts
from .readable import readable_front
from .residual_figure import residual_figure, residuals

SHOWN_HERE = {"front", "anchors", "log", "knee_prediction"}


def _figure(report, make, alt, caption):
    name = report.figures.draw(make)
    return [page.image_figure(name, alt, caption)] if name else []


def _knee_text(data, shown):
    knee = data.knee()
    if knee is None:
        return "no knee marked"
    return f"member {knee}: {shown[knee]}"


def _knee_formula(report, data, shown):
    """The knee typeset (SymPy's LaTeX of its rounded expression, temporaries substituted), if it can be."""
    knee = data.knee()
    if knee is None:
        return []
    try:
        formula = latex(shown[knee], data.inputs)
    except Exception:  # noqa: BLE001 - a text SymPy cannot take is shown as text only
        return []
    if not formula:
        return []
    figure = formula_figure(formula)
    if figure is None:
        return []
    return _figure(report, lambda: figure, f"{data.path.rstrip('/')} knee formula",
                   "the knee typeset (SymPy's form: like terms and constant products combined, those shown to 4 "
                   "digits)")


def _test_choice(data):
    """Which member the test rows favour (pbrfit export --member test), beside the training RMSE's choice."""
    test = data.front["test_rmse"]
    if not np.any(np.isfinite(test)):
        return [page.paragraph("No test rows: every error is on the rows the search fitted (hold rows out with "
                               "dataset.test_fraction to see how members do on others).")]
    best = int(np.nanargmin(test))
    return [page.paragraph(f"On the test rows the lowest RMSE is member {best}'s ({number(test[best])}, against "
                           f"{number(data.front['rmse'][best])} on the training rows); pbrfit export --member test "
                           "exports it.")]


def _front_parts(report, data, shown):
    path = data.path.rstrip("/")
    parts = [page.heading(3, f"{path}/front and {path}/anchors")]
    if len(data.front) == 0:
        return parts + [page.paragraph("No front yet: the job has not finished its last stage, which measures the "
                                       "front and the anchors.")]
    parts.append(page.paragraph(f"{len(data.front)} members by increasing cost; the knee (the default of "
                                f"pbrfit export) is {_knee_text(data, shown)}. Constants are rounded to the fewest "
                                "digits that leave the RMSE's printed digits unchanged; 'exact' shows the text "
                                "as found."))
    parts += _test_choice(data)
    parts += _knee_formula(report, data, shown)
    parts += _figure(report, lambda: front_figure(data, shown), f"{path}/front",
                     f"{path}/front (front) and {path}/anchors (anchors): RMSE filled, max abs error hollow, the "
                     "knee ringed, anchors as stars; labels: row and shortened expression")
    return parts + [page.beside([page.heading(4, "front") + front_markup(data, shown),
                                 page.heading(4, "anchors") + anchors_markup(data)])]


def _residual_parts(report, data):
    path = f"{data.path.rstrip('/')}/knee_prediction"
    parts = [page.heading(3, path)]
    if len(data.knee_prediction) == 0:
        return parts + [page.paragraph("No knee predictions yet.")]
    r = residuals(data)
    caption = (f"{path} (residuals): prediction - target at {r.size} training rows; RMSE "
               f"{number(float(np.sqrt(np.mean(r * r))))}, largest |residual| {number(float(np.max(np.abs(r))))}")
    return parts + _figure(report, lambda: residual_figure(data), path, caption)


def _log_parts(report, data):
    path = f"{data.path.rstrip('/')}/log"
    parts = [page.heading(3, path)]
    if len(data.log) == 0:
        return parts + [page.paragraph("No epoch finished yet.")]
    epochs = np.unique(data.log["epoch"]).size
    return parts + _figure(report, lambda: log_figure(data), path,
                           f"{path}: {len(data.log)} rows, {epochs} epochs; best_error is the search's error measure")


def _overview_row(data):
    knee = data.knee()
    if knee is None:
        return [data.path, ", ".join(data.inputs), str(len(data.front)), "–", "–", "–", "–"]
    m = data.front[knee]
    exact = texts(data.front, "expression")[knee]
    return [data.path, ", ".join(data.inputs), str(len(data.front)), str(knee),
            page.with_exact_text(readable_front(data)[knee], exact), number(m["cost"]), number(m["rmse"])]


@register("symreg")
class SymregRenderer(Renderer):
    def kind_sections(self, report):
        outputs = [read_output(g, ("front", "knee_prediction")) for g in report.groups if is_output_group(g)]
        rows = [_overview_row(data) for data in outputs]
        header = ["output", "inputs", "front members", "knee", "knee expression", "knee cost", "knee RMSE"]
        return [page.section([page.heading(2, "Symbolic regression", "symreg"),
                              page.table(header, rows, (2, 3, 5, 6))])]

    def output_section(self, report, group, anchor):
        data = read_output(group)
        shown = readable_front(data)
        parts = self.group_header(group, anchor)
        parts += guarded(lambda: _front_parts(report, data, shown), group.path)
        for make in (_residual_parts, _log_parts):
            parts += guarded(lambda: make(report, data), group.path)
        for table in (t for t in group.tables if t.name not in SHOWN_HERE):
            parts += self.rows_section(table)
        return page.section(parts)

    def recurring_section(self, group, anchor):
        parts = self.group_header(group, anchor)
        for table in group.tables:
            if table.name != "recurring":
                parts += self.rows_section(table)
                continue
            records = table.dataset[()]
            parts.append(page.heading(3, table.path))
            parts.append(page.paragraph(f"{len(records)} sub-expressions of two or more operations found in several "
                                        "front members, by the number of members" if len(records) else
                                        "No sub-expression recurs across the front members."))
            parts += guarded(lambda: [recurring_markup(records)] if len(records) else [], table.path)
        return page.section(parts)

    def render(self, report):
        report.groups.sort(key=lambda g: g.path == "/subexpressions")  # after the outputs it draws on
        return super().render(report)

    def group_section(self, report, group, anchor):
        if is_output_group(group):
            return self.output_section(report, group, anchor)
        if group.path == "/subexpressions":
            return self.recurring_section(group, anchor)
        return super().group_section(report, group, anchor)
