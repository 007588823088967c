# The result file as groups of axes and tables, in path order, the root first when it holds datasets.
# An axis is a 1-D numeric dataset that is an HDF5 dimension scale; every other dataset is a table.
# Only reads metadata: values are read later, by tables.py.
from dataclasses import dataclass, field

import h5py

from .attributes import string_attribute
from .tables import Axis, describe_table

# Attributes HDF5's dimension-scale API keeps for itself; not settings of the result.
BOOKKEEPING = frozenset({"CLASS", "NAME", "REFERENCE_LIST", "DIMENSION_LIST", "DIMENSION_LABELS"})


@dataclass
class Group:
    path: str
    node: h5py.Group
    description: str
    axes: list = field(default_factory=list)
    tables: list = field(default_factory=list)


def is_axis(dataset):
    try:
        return dataset.ndim == 1 and dataset.dtype.kind in "fiu" and h5py.h5ds.is_scale(dataset.id)
    except Exception:  # noqa: BLE001 - unusual dataset types are tables, not axes
        return False


def _group_of(path, node):
    group = Group(path, node, string_attribute(node, "description"))
    for name in sorted(node.keys()):
        child = node.get(name)
        if isinstance(child, h5py.Dataset) and is_axis(child):
            group.axes.append(Axis.read(name, child))
    for name in sorted(node.keys()):
        child = node.get(name)
        if isinstance(child, h5py.Dataset) and not is_axis(child):
            group.tables.append(describe_table(path, name, child, group.axes))
    return group


def walk(file):
    """Every group that holds datasets, each once, in path order ("/" first)."""
    paths = ["/"]
    file.visit(lambda name: paths.append("/" + name) if isinstance(file.get(name), h5py.Group) else None)
    groups = [_group_of(path, file[path]) for path in paths]
    return [g for g in groups if g.axes or g.tables or g.path != "/"]
