# The figure of a 2-D numeric table: a map over its two axes (the outer one along y) with a colour bar,
# titled group/table, cells not yet computed in the scale's "not computed" colour.
from .colour_scale import finite_values
from .figure_parts import label, new_figure, not_computed_note, show_no_values, title
from .map_drawing import add_colour_bar, draw_map


def heat_map_figure(table, scale):
    values, _ = table.grid_values()
    figure = new_figure(6.4, 4.8)
    ax = figure.add_subplot()
    artist = draw_map(ax, values, table.axis_values(1), table.axis_values(0), scale)
    add_colour_bar(figure, artist, ax, scale)
    if finite_values(values).size == 0:
        show_no_values(ax)
    ax.set_xlabel(label(table.axis_label(1)))
    ax.set_ylabel(label(table.axis_label(0)))
    title(ax, table.path, not_computed_note(values))
    return figure
