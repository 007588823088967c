# One output's front and anchors as HTML tables (texts escaped by html_page): every member with its
# expression for people (constants rounded, readable.py; the exact text a click away) and metrics, the knee marked; every anchor with its metrics beside the front member of
# lowest RMSE among those costing at most the anchor's cost, and how the two RMSEs compare.
import numpy as np

from ... import html_page as page
from ...statistics import number
from .output_tables import texts

FRONT_HEADER = ["member", "expression", "cost", "operations", "piecewise", "RMSE", "max abs error", "test RMSE",
                "generation", "knee"]
ANCHOR_HEADER = ["anchor", "expression", "cost", "operations", "RMSE", "max abs error",
                 "our best at cost <= anchor's", "its cost", "its RMSE", "its max abs error", "RMSE: ours vs anchor"]


def front_markup(data, shown):
    """shown: the members' expressions for people (readable.readable_front), the exact texts a click away."""
    front = data.front
    rows = []
    for k, expression in enumerate(texts(front, "expression")):
        m = front[k]
        rows.append([str(k), page.with_exact_text(shown[k], expression), number(m["cost"]), str(int(m["operations"])), str(int(m["piecewise"])),
                     number(m["rmse"]), number(m["max_abs_error"]), number(m["test_rmse"]), str(int(m["generation"])),
                     "knee" if m["knee"] == 1 else ""])
    return page.table(FRONT_HEADER, rows, (0, 2, 3, 4, 5, 6, 7, 8))


def best_at_cost(front, cost):
    """The row of the lowest-RMSE member costing at most `cost`, or None when none does."""
    rows = np.flatnonzero(front["cost"] <= cost)
    if rows.size == 0 or np.all(np.isnan(front["rmse"][rows])):
        return None
    return int(rows[np.nanargmin(front["rmse"][rows])])


def comparison_text(ours, theirs):
    if ours == theirs:
        return "equal"
    if theirs == 0:
        return "the anchor is exact (RMSE 0)"
    if ours == 0:
        return "ours is exact (RMSE 0)"
    ratio = ours / theirs
    return f"ours {ratio:.3g} x the anchor's: " + ("ours lower" if ours < theirs else "the anchor lower")


def _anchor_row(front, name, expression, anchor):
    row = [name, expression, number(anchor["cost"]), str(int(anchor["operations"])), number(anchor["rmse"]),
           number(anchor["max_abs_error"])]
    best = best_at_cost(front, anchor["cost"]) if len(front) else None
    if best is None:
        return row + ["no member costs as little", "–", "–", "–", "–"]
    m = front[best]
    return row + [f"member {best}", number(m["cost"]), number(m["rmse"]), number(m["max_abs_error"]),
                  comparison_text(float(m["rmse"]), float(anchor["rmse"]))]


def anchors_markup(data):
    anchors = data.anchors
    if len(anchors) == 0 or anchors.dtype.names is None:
        return page.paragraph("The job names no anchor for this output.")
    rows = [_anchor_row(data.front, name, expression, anchors[k])
            for k, (name, expression) in enumerate(zip(texts(anchors, "name"), texts(anchors, "expression")))]
    return page.table(ANCHOR_HEADER, rows, (2, 3, 4, 5, 7, 8, 9))


def recurring_markup(records):
    rows = [[text, str(int(members)), outputs] for text, members, outputs in
            zip(texts(records, "subexpression"), records["members"], texts(records, "outputs"))]
    return page.table(["sub-expression", "front members", "outputs"], rows, (1,))
