# The figure of one output's front: RMSE (filled) and max abs error (hollow) on a log axis over cost, the
# RMSE points joined as the front's staircase, test RMSE where there is one; each member labelled with its
# row and its shortened expression (at most MAX_LABELS, evenly chosen, the knee always) in a column right of
# the plot, the labels spread so that none overlaps another and each joined to its point; the knee ringed,
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


def spread(positions, gap):
    """Positions in [0, 1] moved apart to at least `gap` between neighbours, in their order, each as near its
    own as the others allow (labels that must not overlap). Returned in the order given."""
    positions = np.asarray(positions, dtype=np.float64)
    order = np.argsort(positions, kind="stable")
    y = np.clip(positions[order], 0.0, 1.0)
    gap = min(gap, 1.0 / max(len(y) - 1, 1))
    for i in range(1, len(y)):
        y[i] = max(y[i], y[i - 1] + gap)
    if len(y) and y[-1] > 1.0:
        y[-1] = 1.0
        for i in range(len(y) - 2, -1, -1):
            y[i] = min(y[i], y[i + 1] - gap)
    out = np.empty_like(y)
    out[order] = y
    return out


def _draw_members(ax, data, floor, shown, label_gap):
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
    # Labels in a column right of the plot, spread so they never overlap, each joined to its point.
    ax.autoscale_view()
    to_axes = ax.transScale + ax.transLimits
    rows = _labelled_rows(len(front), knee)
    points = [(cost[row], on_log_axis(front["rmse"][row], floor)) for row in rows]
    heights = spread([to_axes.transform(p)[1] for p in points], label_gap)
    for row, point, height in zip(rows, points, heights):
        ax.annotate(f"{row}: {short_expression(shown[row])}", point, xytext=(1.03, height), textcoords="axes fraction",
                    va="center", ha="left", fontsize=7, color=KNEE_COLOUR if row == knee else "#333333",
                    arrowprops={"arrowstyle": "-", "color": "#bbbbbb", "linewidth": 0.6, "shrinkA": 0, "shrinkB": 3})


def _draw_anchors(ax, data, floor, middle):
    for k, (name, cost, rmse) in enumerate(zip(texts(data.anchors, "name"), data.anchors["cost"], data.anchors["rmse"])):
        y = on_log_axis(rmse, floor)
        ax.plot([cost], [y], linestyle="none", marker="*", markersize=14, color=ANCHOR_COLOURS[k % len(ANCHOR_COLOURS)],
                markeredgecolor="black", label=f"anchor: {label(name, 30)}")
        right_half = cost > middle
        ax.annotate(label(name, 30), (cost, y), xytext=(-8 if right_half else 8, -10), textcoords="offset points",
                    ha="right" if right_half else "left", fontsize=8, fontweight="bold")


def front_figure(data, shown):
    """shown: the members' expressions as the labels show them (readable.readable_front)."""
    figure = new_figure(10.5, 5.4)
    ax = figure.add_subplot()
    has_anchors = len(data.anchors) > 0 and data.anchors.dtype.names is not None
    error_sets = [data.front["rmse"], data.front["max_abs_error"]] + ([data.anchors["rmse"]] if has_anchors else [])
    floor = log_floor(*error_sets)
    costs = np.concatenate([data.front["cost"]] + ([data.anchors["cost"]] if has_anchors else []))
    middle = 0.5 * (np.nanmin(costs) + np.nanmax(costs))  # anchor labels right of it extend to the left
    ax.set_yscale("log")
    label_gap = 9.0 / (0.8 * 5.4 * 72)  # a 7-point line over the axes' height, as a fraction of it
    if has_anchors:
        _draw_anchors(ax, data, floor, middle)
    _draw_members(ax, data, floor, shown, label_gap)
    ax.set_xlabel("cost (the job's cost table)")
    ax.set_ylabel("error on the training rows")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="best")
    title(ax, f"{data.path}/front: {len(data.front)} members, error vs cost", floor_note(floor, *error_sets))
    return figure
