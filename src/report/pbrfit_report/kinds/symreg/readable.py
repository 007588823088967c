# A symbolic-regression front's expressions for people (readable_expressions.py): each member's constants
# rounded on the output's training rows, where the file holds them.
import numpy as np

from ...readable_expressions import NotReadable, rounded
from .output_tables import texts


def readable_front(data):
    """The front's expressions for people, one per member (output_tables.OutputTables): rounded where the
    training rows are there to measure the rounding by, else (and for any text that is not readable) as
    written."""
    exact = texts(data.front, "expression")
    rows = data.knee_prediction
    names = rows.dtype.names or ()
    if len(rows) == 0 or "target" not in names or not all(n in names for n in data.inputs):
        return exact
    columns = {n: np.asarray(rows[n], dtype=np.float64) for n in data.inputs}
    target = np.asarray(rows["target"], dtype=np.float64)
    shown = []
    for text, member in zip(exact, data.front):
        try:
            shown.append(rounded(text, data.inputs, columns, target, float(member["rmse"]))[0])
        except (NotReadable, RecursionError):
            shown.append(text)
    return shown
