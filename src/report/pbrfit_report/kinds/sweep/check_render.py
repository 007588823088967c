# The check render of an LTC table (docs/results-sweep.md, "Check render"): the plane under a rectangle
# light as the finished table lights it, beside ground truth and, where there is one, the published table;
# per image how far each is from the truth, as numbers and as a difference map relative to the image's
# brightest truth. Images are shown on one exposure per row (the truth's 99.5th percentile is white), with
# a display gamma of 2.2; pixels without a value (NaN) in grey.
import numpy as np
from matplotlib import colormaps

from ...colour_scale import NOT_COMPUTED_COLOUR
from ...figure_parts import new_figure

TILE_INCHES = 1.9
DIFFERENCE_RANGE = 0.1  # the difference maps' ends: +-10 % of the image's brightest truth


def is_render_group(group):
    names = {t.name for t in group.tables}
    return group.path.endswith("/render") and {"ltc", "reference"} <= names


def render_images(group):
    """{layer: array [image, row, column]} of the layers present with a finite value, and the image axis."""
    node = group.node
    layers = {name: node[name][...] for name in ("ltc", "reference", "published") if name in node}
    layers = {k: v for k, v in layers.items() if np.isfinite(v).any()}
    axis = next(a for a in group.axes if a.name not in ("row", "column"))
    return layers, axis


def image_errors(image, truth):
    """Over the pixels where both are finite: mean |image - truth| / mean truth, and the 95th percentile of
    |image - truth| / the brightest truth."""
    both = np.isfinite(image) & np.isfinite(truth)
    if not both.any() or not truth[both].mean() > 0:
        return float("nan"), float("nan")
    difference = np.abs(image[both] - truth[both])
    return float(difference.mean() / truth[both].mean()), float(np.percentile(difference, 95) / truth[both].max())


def _shown(image, white):
    shown = np.clip(np.nan_to_num(image, nan=0.0) / white, 0.0, 1.0) ** (1.0 / 2.2)
    rgb = np.repeat(shown[..., None], 3, axis=2)
    grey = np.array([int(NOT_COMPUTED_COLOUR[i:i + 2], 16) / 255.0 for i in (1, 3, 5)])
    rgb[~np.isfinite(image)] = grey
    return rgb


def check_render_figure(layers, axis_name, axis_values):
    truth = layers["reference"]
    columns = [("ltc", "this table"), ("reference", "ground truth")]
    if "published" in layers:
        columns.append(("published", "published table"))
    differences = [("ltc", "this table - truth")]
    if "published" in layers:
        differences.append(("published", "published - truth"))
    count = len(columns) + len(differences)
    rows = truth.shape[0]
    figure = new_figure(TILE_INCHES * count + 0.8, TILE_INCHES * rows + 0.4)
    cmap = colormaps["RdBu_r"].with_extremes(bad=NOT_COMPUTED_COLOUR)
    artist = None
    for i in range(rows):
        finite = truth[i][np.isfinite(truth[i])]
        white = float(np.percentile(finite, 99.5)) if finite.size else 1.0
        peak = float(finite.max()) if finite.size else 1.0
        for j, (name, heading) in enumerate(columns):
            ax = figure.add_subplot(rows, count, i * count + j + 1)
            ax.imshow(_shown(layers[name][i], white if white > 0 else 1.0), interpolation="nearest")
            ax.set_xticks([])
            ax.set_yticks([])
            ax.set_title(heading, fontsize=8)
            if j == 0:
                ax.set_ylabel(f"{axis_name} {axis_values[i]:.3g}", fontsize=8)
        for k, (name, heading) in enumerate(differences):
            ax = figure.add_subplot(rows, count, i * count + len(columns) + k + 1)
            relative = (layers[name][i] - truth[i]) / (peak if peak > 0 else 1.0)
            artist = ax.imshow(relative, cmap=cmap, vmin=-DIFFERENCE_RANGE, vmax=DIFFERENCE_RANGE,
                               interpolation="nearest")
            ax.set_xticks([])
            ax.set_yticks([])
            mean, _ = image_errors(layers[name][i], truth[i])
            ax.set_title(f"{heading}\nmean {100 * mean:.2g} % of the truth's", fontsize=8)
    if artist is not None:
        bar = figure.colorbar(artist, ax=figure.axes[-len(differences):], shrink=0.8)
        bar.set_label("difference / brightest truth", fontsize=8)
        bar.ax.tick_params(labelsize=7)
    return figure
