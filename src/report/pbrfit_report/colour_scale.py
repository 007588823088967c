# The colour scale of a map: one colour for cells that are not finite (NaN: not yet computed), a log
# scale for errors and counts whose positive values span more than two decades, and for `start` tables
# one colour per code, labelled from the table's `labels` attribute ("0=cold,1=parent,...").
from dataclasses import dataclass

import numpy as np
from matplotlib import colormaps
from matplotlib.colors import BoundaryNorm, ListedColormap, LogNorm, Normalize

from .start_labels import parse_labels

NOT_COMPUTED_COLOUR = "#c8c8c8"
NOT_COMPUTED_NOTE = "grey: not yet computed (NaN)"
LOG_ROLES = ("error", "anchor_error", "count")
DECADES_FOR_LOG = 2.0


@dataclass
class ColourScale:
    cmap: object
    norm: object
    ticks: list = None
    tick_labels: list = None


def finite_values(values):
    values = np.asarray(values, dtype=np.float64).reshape(-1)
    return values[np.isfinite(values)]


def spans_decades(finite, decades=DECADES_FOR_LOG):
    """True when every value is positive and max / min exceeds 10^decades."""
    return finite.size > 0 and finite.min() > 0 and np.log10(finite.max() / finite.min()) > decades


def _with_not_computed(cmap):
    return cmap.with_extremes(bad=NOT_COMPUTED_COLOUR)


def _categorical(finite, labels):
    codes = sorted(set(int(c) for c in np.unique(np.round(finite))) | set(labels))
    if not codes:
        codes = [0]
    palette = colormaps["tab10"] if len(codes) <= 10 else colormaps["tab20"]
    cmap = _with_not_computed(ListedColormap([palette(i % palette.N) for i in range(len(codes))]))
    boundaries = [c - 0.5 for c in codes] + [codes[-1] + 0.5]
    norm = BoundaryNorm(boundaries, len(codes)) if len(codes) > 1 else Normalize(codes[0] - 0.5, codes[0] + 0.5)
    return ColourScale(cmap, norm, codes, [labels.get(c, str(c)) for c in codes])


def colour_scale(role, value_sets, labels_text=""):
    """The scale for a table of this role whose maps show these arrays (sharing one scale)."""
    finite = np.concatenate([finite_values(v) for v in value_sets]) if value_sets else np.empty(0)
    if role == "start":
        return _categorical(finite, parse_labels(labels_text))
    cmap = _with_not_computed(colormaps["viridis"])
    if finite.size == 0:
        return ColourScale(cmap, Normalize(0.0, 1.0))
    low, high = float(finite.min()), float(finite.max())
    if role in LOG_ROLES and spans_decades(finite):
        return ColourScale(cmap, LogNorm(low, high))
    if low == high:
        low, high = low - 0.5 * (abs(low) or 1.0), high + 0.5 * (abs(high) or 1.0)
    return ColourScale(cmap, Normalize(low, high))
