# Comparisons of our fit errors with a published or reference model's, per `anchor_error` table: over
# the cells where both errors are finite, mean, median and max of each, and the fraction of cells where
# ours <= the anchor's. A pair that cannot be compared (no such `compares_with` table, other shapes,
# not numeric) carries the reason instead of numbers.
from dataclasses import dataclass

import numpy as np

from .statistics import Summary, summarise


@dataclass
class AnchorComparison:
    anchor: str
    anchor_table: str
    ours_table: str
    problem: str = ""
    ours: Summary = None
    theirs: Summary = None
    cells: int = 0
    ours_at_most: int = 0

    def fraction(self):
        return self.ours_at_most / self.cells if self.cells else float("nan")

    def fraction_text(self):
        if not self.cells:
            return "– (no cell where both are finite)"
        return f"{self.fraction():.4f} ({self.ours_at_most} of {self.cells} cells)"


def _compare(anchor_table, ours_table, comparison):
    if not (anchor_table.is_numeric() and ours_table.is_numeric()):
        comparison.problem = "not numeric tables"
        return comparison
    theirs, ours = anchor_table.grid_values()[0], ours_table.grid_values()[0]
    if theirs.shape != ours.shape:
        comparison.problem = f"different shapes {list(ours.shape)} and {list(theirs.shape)}"
        return comparison
    both = np.isfinite(theirs) & np.isfinite(ours)
    comparison.ours, comparison.theirs = summarise(ours[both]), summarise(theirs[both])
    comparison.cells = int(np.count_nonzero(both))
    comparison.ours_at_most = int(np.count_nonzero(ours[both] <= theirs[both]))
    return comparison


def comparisons(group):
    by_name = {t.name: t for t in group.tables}
    out = []
    for table in group.tables:
        if table.role != "anchor_error":
            continue
        target = table.attribute("compares_with").strip()
        comparison = AnchorComparison(table.attribute("anchor") or table.name, table.name, target)
        if target not in by_name:
            comparison.problem = f"no table '{target}' in this group to compare with" if target else \
                "no compares_with attribute"
            out.append(comparison)
            continue
        out.append(_compare(table, by_name[target], comparison))
    return out


def partners(group):
    """{table name: the names sharing its colour scale}: anchor_error tables and the errors they compare
    with, joined transitively (one error compared with two anchors puts all three on one scale)."""
    shared = {}
    names = {t.name for t in group.tables}
    for table in group.tables:
        target = table.attribute("compares_with").strip()
        if table.role == "anchor_error" and target in names:
            merged = shared.get(table.name, {table.name}) | shared.get(target, {target})
            for name in merged:
                shared[name] = merged
    return shared
