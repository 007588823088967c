# The search's progress from one output's `log`: the best error in each island's population over the
# generations it has completed, a line per island (up to MAX_ISLANDS; beyond, the median over the islands
# with the range from best to worst island), on a log axis (errors of 0 at the floor of log_scale.py).
import numpy as np

from ...figure_parts import new_figure, title
from .log_scale import floor_note, log_floor, on_log_axis

MAX_ISLANDS = 16


def _per_island(ax, log, floor):
    for island in np.unique(log["island"]):
        rows = log[log["island"] == island]
        rows = rows[np.argsort(rows["generation"], kind="stable")]
        ax.plot(rows["generation"], on_log_axis(rows["best_error"], floor), marker=".", linewidth=1,
                label=f"island {int(island)}")
    ax.legend(fontsize=7, ncol=2)


def _envelope(ax, log, floor):
    order = np.argsort(log["epoch"], kind="stable")
    starts = np.unique(log["epoch"][order], return_index=True)[1]
    generations = np.split(log["generation"][order].astype(np.float64), starts[1:])
    errors = np.split(on_log_axis(log["best_error"][order], floor), starts[1:])
    generation = [np.median(g) for g in generations]
    ax.fill_between(generation, [np.nanmin(e) for e in errors], [np.nanmax(e) for e in errors], alpha=0.3,
                    label="best to worst island")
    ax.plot(generation, [np.nanmedian(e) for e in errors], linewidth=1.5, label="median island")
    ax.legend(fontsize=8)


def log_figure(data):
    """Drawn only when the log has rows."""
    log = data.log
    floor = log_floor(log["best_error"])
    figure = new_figure(7.0, 4.2)
    ax = figure.add_subplot()
    islands = np.unique(log["island"]).size
    (_per_island if islands <= MAX_ISLANDS else _envelope)(ax, log, floor)
    ax.set_yscale("log")
    ax.set_xlabel("generation")
    ax.set_ylabel("best error in the island (search measure)")
    ax.grid(True, which="both", alpha=0.3)
    title(ax, f"{data.path}/log: best error per island, {islands} islands", floor_note(floor, log["best_error"]))
    return figure
