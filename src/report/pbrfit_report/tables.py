# One table of a result: its kind (grid: a numeric array over axes; rows: records, texts, or a growing
# table whose first dimension is not an axis), its role (result conventions, docs/report.md) and its
# values. grid_values() is always float64 with the full extent of the axes: rows the writer has not
# reached yet (a run in progress) read as NaN. Very large grids are read with a stride, so a figure
# never needs more than MAX_GRID_ELEMENTS numbers.
import math
from dataclasses import dataclass, field

import numpy as np

from .attributes import string_attribute

MAX_GRID_ELEMENTS = 1 << 22


@dataclass
class Axis:
    name: str
    values: np.ndarray
    description: str = ""

    @staticmethod
    def read(name, dataset):
        return Axis(name, np.asarray(dataset[()], dtype=np.float64).reshape(-1),
                    string_attribute(dataset, "description"))

    def label(self):
        return f"{self.name} ({self.description})" if self.description else self.name


@dataclass
class Table:
    group_path: str
    name: str
    dataset: object
    description: str
    role: str
    dimension_names: list
    axes: list                 # per dimension: an Axis, or None (no axis: the rows of a growing table)
    kind: str                  # "grid" or "rows"
    _grid: object = field(default=None, repr=False)

    @property
    def path(self):
        return self.group_path.rstrip("/") + "/" + self.name

    def attribute(self, name, default=""):
        return string_attribute(self.dataset, name, default)

    def is_numeric(self):
        return self.dataset.ndim > 0 and _is_numeric(self.dataset)

    def row_count(self):
        return int(self.dataset.shape[0]) if self.dataset.ndim else 1

    def extent(self):
        return tuple(len(a.values) if a is not None else n for a, n in zip(self.axes, self.dataset.shape))

    def grid_values(self):
        """(values, steps): the table as float64 over its full extent, and the stride used per dimension."""
        if self._grid is None:
            self._grid = _read_grid(self.dataset, self.extent())
        return self._grid

    def forget_values(self):
        self._grid = None

    def axis_values(self, dimension):
        """The positions along one dimension (the axis, or 0, 1, ...), at the stride grid_values() used."""
        step = self.grid_values()[1][dimension]
        axis = self.axes[dimension]
        values = axis.values if axis is not None else np.arange(self.extent()[dimension], dtype=np.float64)
        return values[::step]

    def axis_label(self, dimension):
        axis = self.axes[dimension]
        return axis.label() if axis is not None else self.dimension_names[dimension]


def _strides(extent):
    total = math.prod(extent)
    if total <= MAX_GRID_ELEMENTS:
        return [1] * len(extent)
    step = math.ceil((total / MAX_GRID_ELEMENTS) ** (1.0 / len(extent)))
    return [max(1, min(step, n)) for n in extent]


def _read_grid(dataset, extent):
    if dataset.ndim == 0:
        return np.asarray([float(dataset[()])]), [1]
    steps = _strides(extent)
    stored = np.asarray(dataset[tuple(slice(None, None, s) for s in steps)], dtype=np.float64)
    wanted = tuple(math.ceil(n / s) for n, s in zip(extent, steps))
    if stored.shape == wanted:
        return stored, steps
    values = np.full(wanted, np.nan)
    values[tuple(slice(0, min(a, b)) for a, b in zip(stored.shape, wanted))] = \
        stored[tuple(slice(0, min(a, b)) for a, b in zip(stored.shape, wanted))]
    return values, steps


def _is_numeric(dataset):
    return dataset.dtype.names is None and dataset.dtype.kind in "fiub"


def _scale_axis(dataset, dimension):
    try:
        scales = dataset.dims[dimension]
        if len(scales):
            scale = scales[0]
            return Axis.read(scale.name.rsplit("/", 1)[-1], scale)
    except Exception:  # noqa: BLE001 - a broken dimension list leaves the dimension without an axis
        pass
    return None


def _axis_of(dataset, dimension, axes_by_name, name):
    """The attached dimension scale; else the group's axis of that name, except along the unlimited
    first dimension (which, without a scale, counts the rows of a growing table)."""
    axis = _scale_axis(dataset, dimension)
    if axis is None and not (dimension == 0 and dataset.maxshape[0] is None):
        axis = axes_by_name.get(name)
    return axis if axis is not None and len(axis.values) >= dataset.shape[dimension] else None


def _dimension_names(dataset):
    listed = [n.strip() for n in string_attribute(dataset, "axes").split(",") if n.strip()]
    if len(listed) == dataset.ndim:
        return listed
    return [f"dim{d}" for d in range(dataset.ndim)]


def describe_table(group_path, name, dataset, group_axes):
    names = _dimension_names(dataset)
    by_name = {a.name: a for a in group_axes}
    axes = [_axis_of(dataset, d, by_name, names[d]) for d in range(dataset.ndim)]
    growing = dataset.ndim > 0 and dataset.maxshape[0] is None and axes[0] is None
    kind = "grid" if dataset.ndim > 0 and _is_numeric(dataset) and not growing else "rows"
    role = string_attribute(dataset, "role").strip() or "output"
    return Table(group_path, name, dataset, string_attribute(dataset, "description"), role, names, axes, kind)
