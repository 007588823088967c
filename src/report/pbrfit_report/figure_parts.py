# Pieces every figure shares: a new constrained-layout Figure (no pyplot, no global state), axis labels
# shortened to fit, titles with a second line counting what is not yet computed, and the placeholder of
# a table that has no finite value yet.
import textwrap

import numpy as np
from matplotlib.figure import Figure

from .colour_scale import NOT_COMPUTED_NOTE

LABEL_WIDTH = 70


def new_figure(width=6.4, height=4.8):
    return Figure(figsize=(width, height), layout="constrained")


def label(text, width=LABEL_WIDTH):
    return textwrap.shorten(" ".join(str(text).split()), width=width, placeholder="...") or " "


def not_computed_note(values, on_map=True):
    """"" when every value is finite, else how many are not, e.g. "grey: not yet computed (NaN): 4 of 48 cells"."""
    missing = int(np.count_nonzero(~np.isfinite(values)))
    if not missing:
        return ""
    what = f"{missing} of {np.size(values)} " + ("cells" if on_map else "entries")
    return f"{NOT_COMPUTED_NOTE}: {what}" if on_map else f"not yet computed (NaN): {what}"


def title(ax_or_figure, text, note=""):
    """A title shortened to fit, with the note (if any) as a smaller second line."""
    full = label(text) + (f"\n{note}" if note else "")
    if hasattr(ax_or_figure, "set_title"):
        ax_or_figure.set_title(full, fontsize=11 if not note else 10)
    else:
        ax_or_figure.suptitle(full, fontsize=11 if not note else 10)


def show_no_values(ax):
    ax.text(0.5, 0.5, "no values yet", ha="center", va="center", transform=ax.transAxes)
