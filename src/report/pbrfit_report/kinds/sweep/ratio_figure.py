# The map of our error over a published model's, cell by cell (anchor_error tables: docs/results-sweep.md),
# on a log2 scale centred on 1: blue where ours is smaller, red where it is larger, white where they are
# equal; cells where either is not finite (not yet computed, or off the published grid) in grey.
import numpy as np
from matplotlib import colormaps
from matplotlib.colors import TwoSlopeNorm

from ...colour_scale import ColourScale, NOT_COMPUTED_COLOUR
from ...figure_parts import label, new_figure, title
from ...map_drawing import add_colour_bar, draw_map

RATIO_RANGE = 8.0  # the scale's ends: 8 times smaller and 8 times larger


def error_ratio(ours, theirs):
    """ours / theirs where both are finite and theirs > 0, else NaN."""
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(np.isfinite(ours) & np.isfinite(theirs) & (theirs > 0), ours / theirs, np.nan)
    return np.where(ratio == 0, 1.0 / RATIO_RANGE, ratio)  # an exact fit shows as the scale's blue end


def ratio_figure(ours_table, anchor_table, anchor_name):
    ours, theirs = ours_table.grid_values()[0], anchor_table.grid_values()[0]
    ratio = error_ratio(ours, theirs)
    cmap = colormaps["RdBu_r"].with_extremes(bad=NOT_COMPUTED_COLOUR)
    scale = ColourScale(cmap, TwoSlopeNorm(0.0, -np.log2(RATIO_RANGE), np.log2(RATIO_RANGE)),
                        [-3, -2, -1, 0, 1, 2, 3], ["1/8", "1/4", "1/2", "1", "2", "4", "8"])
    figure = new_figure(6.4, 4.8)
    ax = figure.add_subplot()
    logs = np.clip(np.log2(ratio), -np.log2(RATIO_RANGE), np.log2(RATIO_RANGE))
    artist = draw_map(ax, logs, ours_table.axis_values(1), ours_table.axis_values(0), scale)
    add_colour_bar(figure, artist, ax, scale)
    ax.set_xlabel(label(ours_table.axis_label(1)))
    ax.set_ylabel(label(ours_table.axis_label(0)))
    finite = ratio[np.isfinite(ratio)]
    note = (f"ours <= theirs in {np.count_nonzero(finite <= 1)} of {finite.size} cells; median ratio "
            f"{np.median(finite):.3g}") if finite.size else "no cell where both are finite"
    title(ax, f"{ours_table.name} ours / {anchor_name}", note)
    return figure
