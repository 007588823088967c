# The generic report, for every job kind: the run summary, then per group (in path order) its
# description, attributes, axes, a summary of its numeric tables, its anchor comparisons, a figure per
# numeric table (line, map or small multiples by rank; errors also a histogram; a table whose computed
# cells all hold one value gets a line saying so instead) and the rows of its
# record, text and growing tables. Kinds add sections by subclassing Renderer (kinds/). A table that
# cannot be drawn gets a note instead of its figure; only RunProblems (cannot write) end the report.
import numpy as np

from . import html_page as page
from .anchors import comparisons, partners
from .attributes import attribute_texts, string_attribute
from .colour_scale import colour_scale, finite_values
from .heat_map import heat_map_figure
from .histogram import histogram_figure
from .line_plot import line_figure
from .problems import RunProblem
from .result_tree import BOOKKEEPING
from .row_tables import rows_markup
from .run_summary import run_summary_markup
from .small_multiples import small_multiples_figure
from .start_labels import start_counts_text
from .statistics import number, summarise

ERROR_ROLES = ("error", "anchor_error")
TABLE_SETTINGS_SHOWN_ELSEWHERE = {"description", "axes", "role"}


class Report:
    """What renderers share: the open file, its groups, where figures go, and notes for the page top."""

    def __init__(self, file, result_path, groups, figures):
        self.file, self.result_path, self.groups, self.figures = file, result_path, groups, figures
        self.notes = []


def _group_attribute_rows(group):
    if group.path == "/":
        return []  # the root's attributes are the run summary
    return [[n, v] for n, v in attribute_texts(group.node) if n != "description" and n not in BOOKKEEPING]


def _axes_markup(group):
    rows = [[a.name, str(a.values.size), number(a.values[0]) if a.values.size else "–",
             number(a.values[-1]) if a.values.size else "–", a.description] for a in group.axes]
    return page.table(["axis", "points", "first", "last", "description"], rows, (1, 2, 3)) if rows else ""


def _summary_row(t):
    try:
        s = summarise(t.grid_values()[0])
    except Exception as error:  # noqa: BLE001 - the figure's place will say so too
        return [t.name, t.role, "", str(t.dataset.dtype)] + ["–"] * 6 + [f"cannot be read: {error}"]
    return [t.name, t.role, " x ".join(str(n) for n in t.extent()), str(t.dataset.dtype), str(s.finite),
            str(s.cells - s.finite), number(s.minimum), number(s.median), number(s.mean), number(s.maximum),
            t.description]


def _summary_markup(grids):
    rows = [_summary_row(t) for t in grids]
    header = ["table", "role", "shape", "type", "finite", "not yet computed", "min", "median", "mean", "max",
              "description"]
    return page.table(header, rows, (4, 5, 6, 7, 8, 9)) if rows else ""


def _comparison_markup(group):
    rows = []
    for c in comparisons(group):
        if c.problem:
            rows.append([c.ours_table, c.anchor, c.anchor_table, "–"] + ["–"] * 6 + [c.problem])
            continue
        rows.append([c.ours_table, c.anchor, c.anchor_table, str(c.cells),
                     number(c.ours.mean), number(c.theirs.mean), number(c.ours.median), number(c.theirs.median),
                     number(c.ours.maximum), number(c.theirs.maximum), c.fraction_text()])
    if not rows:
        return ""
    header = ["ours", "anchor", "anchor table", "cells", "mean ours", "mean anchor", "median ours",
              "median anchor", "max ours", "max anchor", "fraction ours <= anchor"]
    return page.heading(3, "Compared with published models") + page.table(header, rows, (3, 4, 5, 6, 7, 8, 9))


def _caption(table):
    extra = [f"{n}={v}" for n, v in attribute_texts(table.dataset)
             if n not in TABLE_SETTINGS_SHOWN_ELSEWHERE and n not in BOOKKEEPING and not n.startswith("field_")]
    values, steps = table.grid_values()
    sampled = [] if all(s == 1 for s in steps) else [f"drawn every {steps} cells of {list(table.extent())}"]
    starts = [f"cells won: {start_counts_text(values, table.attribute('labels'))}"] if table.role == "start" else []
    missing = int(np.count_nonzero(~np.isfinite(values)))
    pending = [f"{missing} of {values.size} cells not yet computed"] if missing else []
    parts = [f"{table.path} ({table.role})", table.description] + extra + starts + pending + sampled
    return "; ".join(p for p in parts if p)


class Renderer:
    """The generic report; a job kind subclasses it and overrides kind_sections (or more)."""

    def kind_sections(self, report):
        return []

    def table_figures(self, report, group, table, scale_groups):
        finite = finite_values(table.grid_values()[0])
        if finite.size > 1 and finite.min() == finite.max() and table.role != "start":
            return [page.paragraph(f"{table.path}: every computed cell is {number(finite[0])} ({table.description}); "
                                   "no figure", "note")]
        shared = [t for t in group.tables if t.name in scale_groups.get(table.name, {table.name})]
        values = [t.grid_values()[0] for t in shared]
        scale = colour_scale(table.role, values, table.attribute("labels"))
        rank = table.grid_values()[0].ndim
        makers = [lambda: line_figure(table)] if rank == 1 else \
            [lambda: heat_map_figure(table, scale)] if rank == 2 else [lambda: small_multiples_figure(table, scale)]
        if table.role in ERROR_ROLES:
            makers.append(lambda: histogram_figure(table))
        caption = _caption(table)
        out = []
        for make in makers:
            name = report.figures.draw(make)
            if name:
                out.append(page.image_figure(name, table.path, caption))
        return out

    def group_figures(self, report, group):
        scale_groups = partners(group)
        out = []
        for table in (t for t in group.tables if t.kind == "grid"):
            out.extend(guarded(lambda: self.table_figures(report, group, table, scale_groups), table.path))
        return out

    def group_header(self, group, anchor):
        """The group's heading (with its anchor), description and attributes."""
        parts = [page.heading(2, group.path, anchor), page.paragraph(group.description) if group.description else ""]
        attributes = _group_attribute_rows(group)
        if attributes:
            parts.append(page.table(["attribute", "value"], attributes))
        return parts

    def rows_section(self, table):
        """A record, text or growing table as its first rows."""
        parts = [page.heading(3, table.path), page.paragraph(table.description) if table.description else ""]
        return parts + guarded(lambda: [rows_markup(table)], table.path)

    def group_section(self, report, group, anchor):
        grids = [t for t in group.tables if t.kind == "grid"]
        parts = self.group_header(group, anchor)
        parts += [_axes_markup(group), _summary_markup(grids), _comparison_markup(group)]
        parts += self.group_figures(report, group)
        for table in (t for t in group.tables if t.kind == "rows"):
            parts += self.rows_section(table)
        for table in group.tables:
            table.forget_values()  # a group's numbers are not kept while the next one is drawn
        return page.section(parts)

    def render(self, report):
        groups = [(g, f"group-{i + 1}") for i, g in enumerate(report.groups)]
        # The kind's sections first: they answer the questions, so they keep their figures under the cap.
        first = self.kind_sections(report)
        sections = first + [self.group_section(report, g, anchor) for g, anchor in groups]
        if report.figures.left_out:
            report.notes.append(f"{report.figures.left_out} figures were left out: a report draws at most "
                                f"{report.figures.limit}.")
        contents = page.bullet_list([page.link("#run", "Run")] + [page.link("#" + a, g.path) for g, a in groups])
        return [page.heading(1, "pbrfit report: " + string_attribute(report.file, "job_name", "?"))] + \
            [page.paragraph(n, "note") for n in report.notes] + \
            [contents, run_summary_markup(report.file, report.result_path)] + sections


def guarded(make_markup, path):
    """make_markup(), or a note saying why it failed: one odd table does not cost the whole report."""
    try:
        return make_markup()
    except RunProblem:
        raise
    except Exception as error:  # noqa: BLE001 - one odd table must not cost the whole report
        return [page.paragraph(f"{path}: cannot be shown: {type(error).__name__}: {error}", "note")]

