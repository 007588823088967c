# The knee member's residuals (prediction - target) at the training rows, from `knee_prediction`:
#  - one input: target and prediction over the input, and the residuals below;
#  - two inputs on a grid (every pair of their values at most once, and the values' product at most
#    twice the rows, as for rows taken from a pbrfit table): a map over the grid (the first input along y),
#    cells without a row grey; other rows: a scatter over the two inputs coloured by residual;
#  - more inputs: the residuals over each input (at most MAX_PANELS), one panel each.
# Residual colours are diverging and centred on 0. Curves and scatters draw at most MAX_POINTS rows (evenly
# strided, the title says so); a grid map draws every cell.
import math

import numpy as np
from matplotlib import colormaps
from matplotlib.colors import Normalize

from ...colour_scale import NOT_COMPUTED_COLOUR, ColourScale
from ...figure_parts import label, new_figure, title
from ...map_drawing import add_colour_bar, draw_map

MAX_PANELS = 8
COLUMNS = 4
MAX_POINTS = 100_000


def residuals(data):
    rows = data.knee_prediction
    return rows["prediction"] - rows["target"]


def _diverging(values):
    finite = values[np.isfinite(values)]
    reach = float(np.abs(finite).max()) if finite.size else 0.0
    reach = reach or 1.0
    return ColourScale(colormaps["RdBu_r"].with_extremes(bad=NOT_COMPUTED_COLOUR), Normalize(-reach, reach))


def grid_of(a, b, values):
    """(a values, b values, values[a, b] with NaN where no row) when the rows form a grid, else None."""
    ua, ia = np.unique(a, return_inverse=True)
    ub, ib = np.unique(b, return_inverse=True)
    if ua.size * ub.size > 2 * values.size or np.unique(ia * ub.size + ib).size != values.size:
        return None
    grid = np.full((ua.size, ub.size), np.nan)
    grid[ia, ib] = values
    return ua, ub, grid


def stride(count):
    return max(1, math.ceil(count / MAX_POINTS))


def _one_input(data, residual):
    x = data.knee_prediction[data.inputs[0]]
    order = np.argsort(x, kind="stable")[::stride(x.size)]
    figure = new_figure(7.0, 5.6)
    top, bottom = figure.subplots(2, 1, sharex=True, height_ratios=[2, 1])
    top.plot(x[order], data.knee_prediction["target"][order], linestyle="none", marker=".", label="target")
    top.plot(x[order], data.knee_prediction["prediction"][order], linewidth=1.2, label="prediction (knee)")
    top.legend(fontsize=8)
    top.grid(True, alpha=0.3)
    bottom.axhline(0.0, color="#999999", linewidth=0.8)
    bottom.plot(x[order], residual[order], marker=".", linewidth=0.8, color="#d62728")
    bottom.set_ylabel("residual")
    bottom.set_xlabel(label(data.inputs[0]))
    bottom.grid(True, alpha=0.3)
    return figure, top, stride(x.size)


def _two_inputs(data, residual):
    a, b = (data.knee_prediction[name] for name in data.inputs)
    scale = _diverging(residual)
    figure = new_figure(7.0, 5.4)
    ax = figure.add_subplot()
    grid = grid_of(a, b, residual)
    every = 1 if grid is not None else stride(residual.size)
    if grid is not None:
        artist = draw_map(ax, grid[2], grid[1], grid[0], scale)
    else:
        artist = ax.scatter(b[::every], a[::every], c=residual[::every], cmap=scale.cmap, norm=scale.norm, s=18,
                            edgecolors="none")
    add_colour_bar(figure, artist, ax, scale).set_label("residual")
    ax.set_xlabel(label(data.inputs[1]))
    ax.set_ylabel(label(data.inputs[0]))
    return figure, ax, every


def _per_input(data, residual):
    shown = data.inputs[:MAX_PANELS]
    columns = min(COLUMNS, len(shown))
    figure = new_figure(3.2 * columns + 0.8, 2.8 * math.ceil(len(shown) / columns) + 0.8)
    axes = figure.subplots(math.ceil(len(shown) / columns), columns, squeeze=False)
    every = stride(residual.size)
    for slot, ax in enumerate(axes.flat):
        if slot >= len(shown):
            ax.set_visible(False)
            continue
        ax.axhline(0.0, color="#999999", linewidth=0.8)
        ax.plot(data.knee_prediction[shown[slot]][::every], residual[::every], linestyle="none", marker=".",
                color="#d62728")
        ax.set_xlabel(label(shown[slot], 30), fontsize=8)
        ax.set_ylabel("residual", fontsize=8)
        ax.grid(True, alpha=0.3)
    return figure, figure, every


def residual_figure(data):
    """Drawn only when knee_prediction has rows."""
    residual = residuals(data)
    count = len(data.inputs)
    figure, titled, every = _one_input(data, residual) if count == 1 else \
        _two_inputs(data, residual) if count == 2 else _per_input(data, residual)
    knee = data.knee()
    notes = [f"the first {MAX_PANELS} of {count} inputs"] if count > MAX_PANELS else []
    notes += [f"1 row in {every} of {residual.size} drawn"] if every > 1 else []
    title(titled, f"{data.path}/knee_prediction: residuals of member {knee if knee is not None else '?'} (the knee)",
          "; ".join(notes))
    return figure
