# The figure of one output's front: RMSE (filled) and max abs error (hollow) on a log axis over cost, the
# RMSE points joined as the front's staircase, test RMSE where there is one; each member labelled with its
# row and its shortened expression (at most MAX_LABELS, evenly chosen, the knee always), the knee ringed,
# and each anchor a star of its own colour with its name. Drawn only for a front with members.
import numpy as np

from ...figure_parts import label, new_figure, title
from .log_scale import floor_note, log_floor, on_log_axis
from .output_tables import short_expression, texts

MAX_LABELS = 40
KNEE_COLOUR = "#d62728"
ANCHOR_COLOURS = ("#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#bcbd22", "#17becf")  # none is the knee's


def _labelled_rows(count, knee):
    rows = set(int(i) for i in np.round(np.linspace(0, count - 1, min(count, MAX_LABELS))))
    return sorted(rows | ({knee} if knee is not None else set()))


def _draw_members(ax, data, floor, middle):
    front = data.front
    cost = front["cost"]
    ax.plot(cost, on_log_axis(front["rmse"], floor), drawstyle="steps-post", color="#1f77b4", linewidth=1,
            marker="o", markersize=5, label="RMSE")
    ax.plot(cost, on_log_axis(front["max_abs_error"], floor), linestyle="none", marker="s", markersize=5,
            markerfacecolor="none", color="#7f7f7f", label="max abs error")
    if np.any(np.isfinite(front["test_rmse"])):
        ax.plot(cost, on_log_axis(front["test_rmse"], floor), linestyle="none", marker="x", color="#2ca02c",
                label="test RMSE")
    knee = data.knee()
    if knee is not None:
        ax.plot([cost[knee]], [on_log_axis(front["rmse"][knee], floor)], linestyle="none", marker="o",
                markersize=14, markerfacecolor="none", markeredgewidth=2, color=KNEE_COLOUR, label="knee")
    expressions = texts(front, "expression")
    for n, row in enumerate(_labelled_rows(len(front), knee)):
        right_half = cost[row] > middle
        ax.annotate(f"{row}: {short_expression(expressions[row])}", (cost[row], on_log_axis(front["rmse"][row], floor)),
                    xytext=(-5 if right_half else 5, 5 if n % 2 == 0 else -11), textcoords="offset points",
                    ha="right" if right_half else "left", fontsize=7, color=KNEE_COLOUR if row == knee else "#333333")


def _draw_anchors(ax, data, floor, middle):
    for k, (name, cost, rmse) in enumerate(zip(texts(data.anchors, "name"), data.anchors["cost"], data.anchors["rmse"])):
        y = on_log_axis(rmse, floor)
        ax.plot([cost], [y], linestyle="none", marker="*", markersize=14, color=ANCHOR_COLOURS[k % len(ANCHOR_COLOURS)],
                markeredgecolor="black", label=f"anchor: {label(name, 30)}")
        right_half = cost > middle
        ax.annotate(label(name, 30), (cost, y), xytext=(-8 if right_half else 8, -10), textcoords="offset points",
                    ha="right" if right_half else "left", fontsize=8, fontweight="bold")


def front_figure(data):
    figure = new_figure(8.0, 5.4)
    ax = figure.add_subplot()
    has_anchors = len(data.anchors) > 0 and data.anchors.dtype.names is not None
    error_sets = [data.front["rmse"], data.front["max_abs_error"]] + ([data.anchors["rmse"]] if has_anchors else [])
    floor = log_floor(*error_sets)
    costs = np.concatenate([data.front["cost"]] + ([data.anchors["cost"]] if has_anchors else []))
    middle = 0.5 * (np.nanmin(costs) + np.nanmax(costs))  # labels right of it extend to the left
    _draw_members(ax, data, floor, middle)
    if has_anchors:
        _draw_anchors(ax, data, floor, middle)
    ax.set_yscale("log")
    ax.set_xlabel("cost (the job's cost table)")
    ax.set_ylabel("error on the training rows")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="lower left")
    title(ax, f"{data.path}/front: {len(data.front)} members, error vs cost", floor_note(floor, *error_sets))
    return figure
