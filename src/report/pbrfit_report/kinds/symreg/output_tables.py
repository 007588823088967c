# The tables of one output group of a symreg result (docs/results-symreg.md), read whole: `front`,
# `anchors`, `log` and `knee_prediction` as numpy record arrays (a table the file lacks, or one not asked
# for, reads as no rows),
# and the output's inputs in column order (group attribute `inputs`). Texts are decoded with texts().
from dataclasses import dataclass

import numpy as np

from ...attributes import string_attribute, text_of

TABLES = ("front", "anchors", "log", "knee_prediction")
SHORT_EXPRESSION = 28


@dataclass
class OutputTables:
    path: str
    inputs: list
    front: np.ndarray
    anchors: np.ndarray
    log: np.ndarray
    knee_prediction: np.ndarray

    def knee(self):
        """The knee's row of the front, or None (no front yet, or no row marked)."""
        marked = np.flatnonzero(self.front["knee"] == 1) if _has(self.front, "knee") else []
        return int(marked[0]) if len(marked) else None


def _has(records, field):
    return records.dtype.names is not None and field in records.dtype.names


def texts(records, field):
    return [text_of(v) for v in records[field]] if _has(records, field) else [""] * len(records)


def short_expression(text, width=SHORT_EXPRESSION):
    text = " ".join(text.split())
    return text if len(text) <= width else text[:width - 3] + "..."


def is_output_group(group):
    return any(t.name == "front" and t.role == "front" for t in group.tables)


def read_output(group, tables=TABLES):
    """The output's tables; those not named in `tables` are left empty (not read)."""
    def records(name):
        node = group.node.get(name) if name in tables else None
        return node[()] if node is not None and node.dtype.names else np.zeros(0, dtype=[("none", "f8")])

    inputs = [n.strip() for n in string_attribute(group.node, "inputs").split(",") if n.strip()]
    return OutputTables(group.path, inputs, *(records(name) for name in TABLES))
