# Errors on a log axis: an error of 0 (an exact fit) has no place there, so it is drawn at a floor a
# decade below the smallest positive error drawn (1e-16 when there is none), and the figure says so.
import numpy as np


def log_floor(*value_sets):
    values = np.concatenate([np.asarray(v, dtype=np.float64).reshape(-1) for v in value_sets] or [np.empty(0)])
    positive = values[np.isfinite(values) & (values > 0)]
    return float(positive.min()) / 10.0 if positive.size else 1e-16


def on_log_axis(values, floor):
    values = np.asarray(values, dtype=np.float64)
    return np.where(values <= 0, floor, values)  # NaN (not measured) stays NaN: not drawn


def floor_note(floor, *value_sets):
    """"" when every error is positive, else what the floor stands for."""
    zeros = sum(int(np.count_nonzero(np.asarray(v, dtype=np.float64) == 0)) for v in value_sets)
    return f"{zeros} error{'s' if zeros != 1 else ''} of 0 drawn at {floor:.3g}" if zeros else ""
