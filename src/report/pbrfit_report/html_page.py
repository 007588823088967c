# Static HTML: every text is escaped here (result files can hold anything: markup, quotes, newlines),
# callers pass raw text and get markup back. The page is one self-contained document: inline style, no
# script, no external resource; images by relative path.
import html

STYLE = """
body { font-family: sans-serif; margin: 2em auto; max-width: 72em; padding: 0 1em; color: #222; }
table { border-collapse: collapse; margin: 0.5em 0 1em; font-size: 90%; }
th, td { border: 1px solid #ccc; padding: 0.2em 0.5em; text-align: left; vertical-align: top;
         white-space: pre-wrap; }
th { background: #f0f0f0; }
td.number { text-align: right; font-variant-numeric: tabular-nums; }
pre { background: #f6f6f6; border: 1px solid #ddd; padding: 0.7em; overflow-x: auto; }
figure { display: inline-block; margin: 0.5em 1em 1em 0; vertical-align: top; }
figcaption { font-size: 85%; max-width: 40em; }
.note { color: #7a4b00; }
section { border-top: 2px solid #ddd; margin-top: 2em; }
.beside { display: flex; flex-wrap: wrap; gap: 0 2em; align-items: flex-start; }
details { font-size: 85%; color: #555; } summary { cursor: pointer; }
"""


class Markup(str):
    """Markup made here, which table() places as it is (every other cell text is escaped)."""


def escape(text):
    return html.escape(str(text), quote=True)


def with_exact_text(shown, exact):
    """`shown` (a readable form), and `exact` one click away when it differs."""
    if shown == exact:
        return Markup(escape(shown))
    return Markup(f"{escape(shown)}<details><summary>exact</summary><code>{escape(exact)}</code></details>")


def heading(level, text, anchor=""):
    ident = f' id="{escape(anchor)}"' if anchor else ""
    return f"<h{level}{ident}>{escape(text)}</h{level}>"


def paragraph(text, css_class=""):
    cls = f' class="{escape(css_class)}"' if css_class else ""
    return f"<p{cls}>{escape(text)}</p>"


def preformatted(text):
    return f"<pre>{escape(text)}</pre>"


def link(href, text):
    return f'<a href="{escape(href)}">{escape(text)}</a>'


def bullet_list(items_markup):
    return "<ul>" + "".join(f"<li>{item}</li>" for item in items_markup) + "</ul>"


def image_figure(src, alt, caption):
    return (f'<figure><img src="{escape(src)}" alt="{escape(alt)}">'
            f"<figcaption>{escape(caption)}</figcaption></figure>")


def table(header, rows, numeric_columns=()):
    """header: texts; rows: lists of texts (escaped here) or Markup; numeric_columns: indices right-aligned."""
    head = "".join(f"<th>{escape(h)}</th>" for h in header)
    body = []
    for row in rows:
        cells = []
        for i, cell in enumerate(row):
            cls = ' class="number"' if i in numeric_columns else ""
            cells.append(f"<td{cls}>{cell if isinstance(cell, Markup) else escape(cell)}</td>")
        body.append("<tr>" + "".join(cells) + "</tr>")
    return f"<table><thead><tr>{head}</tr></thead><tbody>{''.join(body)}</tbody></table>"


def beside(markup_parts):
    """Blocks side by side where the page is wide enough, one below the other where it is not."""
    return '<div class="beside">' + "".join(f"<div>{part}</div>" for part in markup_parts) + "</div>"


def section(markup_parts):
    return "<section>" + "\n".join(markup_parts) + "</section>"


def document(title, markup_parts, refresh_seconds=0):
    """The page; with refresh_seconds > 0 the browser reloads it at that interval (a report being remade)."""
    refresh = f"<meta http-equiv=\"refresh\" content=\"{refresh_seconds:g}\">\n" if refresh_seconds > 0 else ""
    return ("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n" + refresh +
            f"<title>{escape(title)}</title>\n<style>{STYLE}</style>\n</head>\n<body>\n"
            + "\n".join(markup_parts) + "\n</body>\n</html>\n")
