# HDF5 attribute values as text for the page: strings (fixed or variable length, bytes decoded as UTF-8
# with replacement), numbers and arrays of either. Never raises for what h5py can read; an attribute h5py
# cannot read is shown as "(unreadable: REASON)".
import numpy as np


def text_of(value):
    if isinstance(value, bytes):
        return value.decode("utf-8", errors="replace")
    if isinstance(value, str):
        return value
    if isinstance(value, np.ndarray):
        if value.ndim == 0:
            return text_of(value[()])
        return ", ".join(text_of(v) for v in value.reshape(-1))
    if isinstance(value, (np.floating, float)):
        return f"{float(value):.10g}"
    if isinstance(value, np.generic):
        return str(value.item())
    return str(value)


def attribute_texts(node):
    """Every attribute of an h5py object as (name, text), in name order."""
    out = []
    for name in sorted(node.attrs.keys()):
        try:
            value = text_of(node.attrs[name])
        except Exception as error:  # noqa: BLE001 - an odd attribute type must not stop the report
            value = f"(unreadable: {error})"
        out.append((name, value))
    return out


def string_attribute(node, name, default=""):
    """A string attribute's text, or default when it is missing or unreadable."""
    try:
        return text_of(node.attrs[name]) if name in node.attrs else default
    except Exception:  # noqa: BLE001
        return default
