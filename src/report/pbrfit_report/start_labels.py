# `start` tables hold integer codes of which start won; their `labels` attribute names the codes
# ("0=cold,1=parent,2=neighbour"). Codes without a label are shown as the number.
import numpy as np


def parse_labels(text):
    """{code: label} from "0=cold,1=parent"; entries that are not CODE=LABEL are ignored."""
    labels = {}
    for entry in text.split(","):
        code, sep, label = entry.partition("=")
        try:
            if sep:
                labels[int(code.strip())] = label.strip()
        except ValueError:
            continue
    return labels


def start_counts_text(values, labels_text):
    """e.g. "cold 16, parent 20, neighbour 12" over the finite cells."""
    values = np.asarray(values, dtype=np.float64).reshape(-1)
    codes, counts = np.unique(np.round(values[np.isfinite(values)]).astype(np.int64), return_counts=True)
    labels = parse_labels(labels_text)
    return ", ".join(f"{labels.get(int(c), str(int(c)))} {int(n)}" for c, n in zip(codes, counts))
