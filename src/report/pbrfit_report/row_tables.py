# Tables shown as rows rather than figures (records, texts, growing tables, scalars): the first
# MAX_ROWS rows as an HTML table with every field (at most MAX_COLUMNS columns), the total row count, and
# the descriptions of record fields (`field_NAME` attributes). Only the rows shown are read.
import numpy as np

from . import html_page as page
from .attributes import text_of

MAX_ROWS = 200
MAX_COLUMNS = 50


def cell_text(value):
    if isinstance(value, (float, np.floating)):
        return f"{float(value):.6g}"
    if isinstance(value, np.ndarray) and value.dtype.kind == "f":
        return ", ".join(f"{v:.6g}" for v in value.reshape(-1))
    return text_of(value)


def _first_rows(dataset):
    if dataset.ndim == 0:
        return np.asarray([dataset[()]])
    inner = tuple(slice(0, min(n, MAX_COLUMNS)) for n in dataset.shape[1:])
    return dataset[(slice(0, min(dataset.shape[0], MAX_ROWS)),) + inner]


def _inner_headers(table, columns):
    if table.dataset.ndim == 2 and table.axes[1] is not None:
        return [f"{table.dimension_names[1]}={v:.4g}" for v in table.axes[1].values[:columns]]
    if table.dataset.ndim == 2:
        return [f"{table.dimension_names[1]} {i}" for i in range(columns)]
    shape = tuple(min(n, MAX_COLUMNS) for n in table.dataset.shape[1:])
    return [str(list(np.unravel_index(i, shape))) for i in range(columns)]


def _layout(table, rows):
    """(header, cell texts per row)."""
    first = table.dimension_names[0] if table.dataset.ndim else "value"
    names = rows.dtype.names
    if names:
        return [first] + list(names), [[str(i)] + [cell_text(r[n]) for n in names] for i, r in enumerate(rows)]
    if rows.ndim <= 1:
        return [first, table.name], [[str(i), cell_text(v)] for i, v in enumerate(rows)]
    flat = rows.reshape(rows.shape[0], int(np.prod(rows.shape[1:])))[:, :MAX_COLUMNS]
    return [first] + _inner_headers(table, flat.shape[1]), [[str(i)] + [cell_text(v) for v in r] for i, r in enumerate(flat)]


def _count_note(table, shown):
    total = table.row_count()
    cut = table.dataset.ndim > 1 and np.prod(table.dataset.shape[1:]) > MAX_COLUMNS
    note = f"{total} row{'s' if total != 1 else ''}" + (f", the first {shown} shown" if shown < total else "")
    return note + (f" (the first {MAX_COLUMNS} values of each row)" if cut else "")


def _field_descriptions(table):
    names = table.dataset.dtype.names or ()
    items = [f"<code>{page.escape(n)}</code>: {page.escape(table.attribute('field_' + n))}"
             for n in names if table.attribute("field_" + n)]
    return page.bullet_list(items) if items else ""


def rows_markup(table):
    rows = _first_rows(table.dataset)
    header, cells = _layout(table, rows)
    return "".join([page.paragraph(f"{table.path}: {_count_note(table, len(cells))}"),
                    _field_descriptions(table), page.table(header, cells)])
