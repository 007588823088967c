# The figure of a 1-D numeric table: its values over its axis (gaps where not yet computed), a log y
# scale for positive errors and counts spanning more than two decades.
import numpy as np

from .colour_scale import LOG_ROLES, finite_values, spans_decades
from .figure_parts import label, new_figure, not_computed_note, show_no_values, title

MARKERS_UP_TO = 64


def line_figure(table):
    values, _ = table.grid_values()
    x = table.axis_values(0)
    figure = new_figure(6.4, 4.0)
    ax = figure.add_subplot()
    finite = finite_values(values)
    if finite.size == 0:
        show_no_values(ax)
    else:
        ax.plot(x, values, marker="." if values.size <= MARKERS_UP_TO else None, linewidth=1.2)
        if table.role in LOG_ROLES and spans_decades(finite):
            ax.set_yscale("log")
    if x.size > 1 and np.all(np.isfinite(x)):
        ax.set_xlim(x.min(), x.max())  # entries not yet computed show as a gap, not a shorter axis
    ax.set_xlabel(label(table.axis_label(0)))
    ax.set_ylabel(label(table.name, 40))
    title(ax, table.path, not_computed_note(values, on_map=False))
    ax.grid(True, alpha=0.3)
    return figure

