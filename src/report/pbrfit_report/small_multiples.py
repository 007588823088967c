# The figure of a numeric table of 3 or more dimensions: maps over its two innermost axes for up to
# MAX_PANELS evenly chosen indices of the outer dimensions (flattened, first and last included), each
# panel titled with its outer axis values, all on one colour scale.
import math

import numpy as np

from .figure_parts import label, new_figure, not_computed_note, title
from .map_drawing import add_colour_bar, draw_map

MAX_PANELS = 8
COLUMNS = 4


def chosen_panels(outer_shape, limit=MAX_PANELS):
    """Flat indices of the outer dimensions: evenly spread, at most limit, the first and last included."""
    count = math.prod(outer_shape)
    return sorted(set(int(i) for i in np.round(np.linspace(0, count - 1, min(limit, count)))))


def _panel_title(table, outer_index):
    parts = []
    for dimension, i in enumerate(outer_index):
        parts.append(f"{table.dimension_names[dimension]}={table.axis_values(dimension)[i]:.4g}")
    return label(", ".join(parts), 48)


def small_multiples_figure(table, scale):
    values, _ = table.grid_values()
    outer_shape = values.shape[:-2]
    panels = chosen_panels(outer_shape)
    columns = min(COLUMNS, len(panels))
    rows = math.ceil(len(panels) / columns)
    figure = new_figure(3.2 * columns + 1.0, 2.8 * rows + 0.8)
    axes = figure.subplots(rows, columns, squeeze=False)
    inner = len(outer_shape)
    for slot, ax in enumerate(axes.flat):
        if slot >= len(panels):
            ax.set_visible(False)
            continue
        outer_index = np.unravel_index(panels[slot], outer_shape)
        artist = draw_map(ax, values[outer_index], table.axis_values(inner + 1), table.axis_values(inner), scale)
        ax.set_title(_panel_title(table, outer_index), fontsize=9)
        ax.set_xlabel(label(table.dimension_names[inner + 1], 30), fontsize=8)
        ax.set_ylabel(label(table.dimension_names[inner], 30), fontsize=8)
    add_colour_bar(figure, artist, axes, scale)
    title(figure, f"{table.path}: {len(panels)} of {math.prod(outer_shape)} slices", not_computed_note(values))
    return figure
