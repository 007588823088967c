# A 2-D array drawn on one matplotlib Axes over its axis positions: rows along y (the outer dimension),
# columns along x. Evenly spaced positions are drawn as an image; geometrically spaced ones as a mesh on
# a log axis; others as a mesh with cell edges half way between positions. Positions that are not
# strictly monotonic or not finite are replaced by indices. Cells that are not finite take the colour
# scale's "not computed" colour.
import numpy as np


def is_monotonic(positions):
    steps = np.diff(positions)
    return positions.size < 2 or bool(np.all(steps > 0) or np.all(steps < 0))


def is_even(positions):
    steps = np.diff(positions)
    return steps.size < 2 or bool(np.allclose(steps, steps[0], rtol=1e-6, atol=0.0))


def cell_edges(positions):
    if positions.size == 1:
        return np.array([positions[0] - 0.5, positions[0] + 0.5])
    middle = 0.5 * (positions[1:] + positions[:-1])
    return np.concatenate([[2 * positions[0] - middle[0]], middle, [2 * positions[-1] - middle[-1]]])


def axis_geometry(positions, count):
    """(cell edges, spacing) along one axis; spacing is "even", "log" or "uneven"."""
    positions = np.asarray(positions, dtype=np.float64)
    if positions.size != count or not np.all(np.isfinite(positions)) or not is_monotonic(positions):
        positions = np.arange(count, dtype=np.float64)
    if is_even(positions):
        return cell_edges(positions), "even"
    if np.all(positions > 0) and is_even(np.log(positions)):
        return np.exp(cell_edges(np.log(positions))), "log"
    return cell_edges(positions), "uneven"


def draw_map(ax, values, x, y, scale):
    """Draws values[y, x]; returns the artist for a colour bar."""
    (xe, x_spacing), (ye, y_spacing) = axis_geometry(x, values.shape[1]), axis_geometry(y, values.shape[0])
    masked = np.ma.masked_invalid(values)
    if x_spacing == y_spacing == "even":
        return ax.imshow(masked, origin="lower", aspect="auto", interpolation="nearest", cmap=scale.cmap,
                         norm=scale.norm, extent=(xe[0], xe[-1], ye[0], ye[-1]))
    artist = ax.pcolormesh(xe, ye, masked, cmap=scale.cmap, norm=scale.norm, shading="flat")
    if x_spacing == "log":
        ax.set_xscale("log")
    if y_spacing == "log":
        ax.set_yscale("log")
    return artist


def add_colour_bar(figure, artist, axes, scale):
    bar = figure.colorbar(artist, ax=axes, ticks=scale.ticks)
    if scale.tick_labels:
        bar.ax.set_yticklabels(scale.tick_labels)
    return bar
