# A formula typeset by matplotlib's mathtext (no TeX installation, no script in the page): one line, the
# figure as wide as the formula. A formula mathtext cannot lay out, or wider than MAX_WIDTH_INCHES, gives
# None, and the page shows the text alone.
from matplotlib.backends.backend_agg import FigureCanvasAgg

from .figure_parts import new_figure

FONT_SIZE = 13
MAX_WIDTH_INCHES = 16.0


def formula_figure(latex):
    figure = new_figure(MAX_WIDTH_INCHES, 0.6)
    figure.set_layout_engine(None)
    canvas = FigureCanvasAgg(figure)
    text = figure.text(0.01, 0.5, f"${latex}$", fontsize=FONT_SIZE, va="center")
    try:
        canvas.draw()
        extent = text.get_window_extent(canvas.get_renderer())
    except (ValueError, RuntimeError):  # mathtext's parse errors
        return None
    width = extent.width / figure.dpi + 0.5  # mathtext measures its last glyphs a little short
    height = max(0.5, extent.height / figure.dpi + 0.25)
    if width > MAX_WIDTH_INCHES:
        return None
    figure.set_size_inches(width, height)
    text.set_position((0.15 / width, 0.5))
    return figure
