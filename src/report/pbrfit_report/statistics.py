# Summary numbers of a numeric table, over its finite values: how many cells are finite and how many
# are not (NaN: not yet computed), min, median, mean and max. Numbers are formatted for the page with
# four significant digits; a table with no finite value shows dashes.
from dataclasses import dataclass

import numpy as np

from .colour_scale import finite_values


@dataclass
class Summary:
    cells: int
    finite: int
    minimum: float = float("nan")
    median: float = float("nan")
    mean: float = float("nan")
    maximum: float = float("nan")


def summarise(values):
    finite = finite_values(values)
    s = Summary(int(np.size(values)), int(finite.size))
    if finite.size:
        s.minimum, s.median = float(finite.min()), float(np.median(finite))
        s.mean, s.maximum = float(finite.mean()), float(finite.max())
    return s


def number(value):
    return "–" if not np.isfinite(value) else f"{value:.4g}"
