# The fitted parameters of a sweep as curves over its axes, as the course draws them: one panel per
# parameter, the value over the innermost axis, one curve per chosen value of the outer axis (up to
# MAX_CURVES, evenly chosen, first and last included) for a grid of two axes. Larger grids are left to the
# generic maps.
import numpy as np

from ...figure_parts import label, new_figure, title

MAX_CURVES = 6
MAX_PANELS = 6


def drawable(tables):
    """The parameter tables this figure can draw: one or two axes."""
    return [t for t in tables if t.role == "parameter" and t.kind == "grid" and t.grid_values()[0].ndim in (1, 2)]


def parameter_curves_figure(tables):
    tables = tables[:MAX_PANELS]
    columns = min(3, len(tables))
    rows = (len(tables) + columns - 1) // columns
    figure = new_figure(4.2 * columns, 3.4 * rows)
    for k, table in enumerate(tables):
        ax = figure.add_subplot(rows, columns, k + 1)
        values = table.grid_values()[0]
        inner = table.axis_values(values.ndim - 1)
        if values.ndim == 1:
            ax.plot(inner, values, linewidth=1.5)
        else:
            outer = table.axis_values(0)
            picks = sorted({int(i) for i in np.round(np.linspace(0, len(outer) - 1, min(len(outer), MAX_CURVES)))})
            for row in picks:
                ax.plot(inner, values[row], linewidth=1.3, label=f"{table.axes[0].name} {outer[row]:.3g}")
            ax.legend(fontsize=7)
        ax.set_xlabel(label(table.axis_label(values.ndim - 1), 40))
        ax.set_ylabel(table.name)
        ax.grid(True, alpha=0.3)
        title(ax, table.name)  # the caption names the group
    return figure
