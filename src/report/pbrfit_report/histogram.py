# The distribution of an error table's finite values: log-spaced bins on a log x axis when the (positive)
# values span more than two decades, even bins otherwise.
import numpy as np

from .colour_scale import finite_values, spans_decades
from .figure_parts import label, new_figure, show_no_values, title

BINS = 50


def histogram_figure(table):
    values, _ = table.grid_values()
    finite = finite_values(values)
    figure = new_figure(6.4, 3.6)
    ax = figure.add_subplot()
    if finite.size == 0:
        show_no_values(ax)
    elif spans_decades(finite):
        ax.hist(finite, bins=np.geomspace(finite.min(), finite.max(), BINS + 1))
        ax.set_xscale("log")
    else:
        ax.hist(finite, bins=BINS)
    ax.set_xlabel(label(table.name, 40))
    ax.set_ylabel("cells")
    title(ax, f"{table.path}: distribution of {finite.size} finite values")
    return figure
