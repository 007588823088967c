# `lut` results (docs/results-lut.md). For a DFG table, first what a reader asks of it: its scale and bias
# as curves over n.v at a few roughnesses, beside the published analytic fit of the same convention (its
# visibility and roughness axis), and how far that fit is from the table over every cell. The generic
# sections then show every table as a map (the error estimate among them).
import numpy as np

from .. import html_page as page
from ..attributes import string_attribute
from ..figure_parts import label, new_figure, title
from ..generic import Renderer, guarded
from ..statistics import number
from . import register

ROUGHNESS_PICKS = (0.1, 0.3, 0.5, 0.7, 0.9)


def karis_2014(n_dot_v, r):
    """Karis's EnvBRDFApprox (Unreal Engine 4 mobile, 2014, after Lazarov 2013), fitted to UE4's table:
    perceptual roughness r (alpha = r^2), Schlick-Smith visibility with k = alpha / 2."""
    c0, c1 = (-1.0, -0.0275, -0.572, 0.022), (1.0, 0.0425, 1.04, -0.04)
    rx, ry, rz, rw = (r * a + b for a, b in zip(c0, c1))
    a004 = np.minimum(rx * rx, np.exp2(-9.28 * n_dot_v)) * rx + ry
    return -1.04 * a004 + rz, 1.04 * a004 + rw


def narkowicz_2014(n_dot_v, g):
    """Narkowicz's analytical DFG term (2014) over gloss g (alpha = (1 - g)^4), separable Smith."""
    v = n_dot_v
    bias = np.clip(np.minimum(-0.1688 * g + 1.895 * g * g, 0.9903 - 4.853 * v + 8.404 * v * v - 5.069 * v ** 3), 0, 1)
    delta = np.clip(0.6045 + 1.699 * g - 0.5228 * v - 3.603 * g * g + 1.404 * g * v + 0.1939 * v * v +
                    2.661 * g ** 3, 0, 1)
    return delta - bias, bias


def pesce_iwanicki_2015(n_dot_v, r):
    """The course's symbolic-regression fit (Pesce & Iwanicki 2015, section 5.3): perceptual roughness r,
    separable Smith visibility."""
    bias = np.exp2(-(7 * n_dot_v + 4 * r * r))
    scale = 1 - bias - r * r * np.maximum(bias, np.minimum(r, 0.739 + 0.323 * n_dot_v) - 0.434)
    return scale, bias


# (visibility, roughness axis name, the parametrization's words): the fit and its name.
FITS = {
    ("separable_schlick", "roughness"): (karis_2014, "Karis 2014 (UE4 mobile)"),
    ("separable", "roughness"): (pesce_iwanicki_2015, "Pesce & Iwanicki 2015"),
    ("separable", "gloss"): (narkowicz_2014, "Narkowicz 2014"),
}


def _convention(group):
    visibility = string_attribute(group.node, "visibility")
    kind = "separable_schlick" if "Schlick" in visibility or "k = alpha / 2" in visibility else \
        "separable" if visibility.startswith("separable") else "height_correlated"
    return kind


def published_fit(group, roughness_axis):
    """(function, name) of the published fit of the table's convention, or None."""
    if "alpha = r^2" not in string_attribute(group.node, "roughness_parametrization") and roughness_axis != "gloss":
        return None
    return FITS.get((_convention(group), roughness_axis))


def _tables(group):
    by_name = {t.name: t for t in group.tables}
    scale, bias = by_name.get("scale"), by_name.get("bias")
    if scale is None or bias is None or scale.grid_values()[0].ndim != 2:
        return None
    names = [a.name if a is not None else "" for a in scale.axes]
    if "n_dot_v" not in names:
        return None
    return scale, bias, names


def _grid(group):
    """(n_dot_v, roughness values, roughness axis name, scale[r, v], bias[r, v]) or None."""
    found = _tables(group)
    if found is None:
        return None
    scale, bias, names = found
    v_dim = names.index("n_dot_v")
    r_dim = 1 - v_dim
    s, b = scale.grid_values()[0], bias.grid_values()[0]
    if v_dim == 0:
        s, b = s.T, b.T
    return scale.axis_values(v_dim), scale.axis_values(r_dim), names[r_dim], s, b


def curves_figure(n_dot_v, roughness, axis_name, scale, bias, fit, fit_name):
    figure = new_figure(10.0, 4.2)
    picks = sorted({int(np.argmin(np.abs(roughness - p))) for p in ROUGHNESS_PICKS})
    colours = [f"C{k}" for k in range(len(picks))]
    for panel, (name, values, which) in enumerate((("scale", scale, 0), ("bias", bias, 1))):
        ax = figure.add_subplot(1, 2, panel + 1)
        for colour, row in zip(colours, picks):
            ax.plot(n_dot_v, values[row], color=colour, linewidth=1.6, label=f"{axis_name} {roughness[row]:.2f}")
            if fit is not None:
                ax.plot(n_dot_v, fit(n_dot_v, roughness[row])[which], color=colour, linewidth=1.2, linestyle="--")
        ax.set_xlabel("n_dot_v")
        ax.set_ylabel(name)
        ax.grid(True, alpha=0.3)
        title(ax, f"dfg/{name}" + (f": ours solid, {fit_name} dashed" if fit else ""))
        if panel == 0:
            ax.legend(fontsize=8)
    return figure


def _fit_rows(n_dot_v, roughness, scale, bias, fit):
    v, r = np.meshgrid(n_dot_v, roughness)
    fitted = fit(v, r)
    rows = []
    for name, ours, theirs in (("scale", scale, fitted[0]), ("bias", bias, fitted[1])):
        difference = np.abs(ours - theirs)
        finite = difference[np.isfinite(difference)]
        if not finite.size:
            continue
        worst = np.unravel_index(np.nanargmax(np.where(np.isfinite(difference), difference, -1)), difference.shape)
        rows.append([name, number(float(np.sqrt(np.mean(finite ** 2)))), number(float(np.percentile(finite, 95))),
                     number(float(finite.max())),
                     f"n_dot_v {n_dot_v[worst[1]]:.3g}, {label(str(roughness[worst[0]]), 12)}"])
    return rows


@register("lut")
class LutRenderer(Renderer):
    def kind_sections(self, report):
        group = next((g for g in report.groups if g.path == "/dfg"), None)
        if group is None:
            return []
        return guarded(lambda: self._dfg_section(report, group), group.path)

    def _dfg_section(self, report, group):
        grid = _grid(group)
        if grid is None:
            return []
        n_dot_v, roughness, axis_name, scale, bias = grid
        found = published_fit(group, axis_name)
        fit, fit_name = found if found else (None, "")
        parts = [page.heading(2, "Scale and bias", "dfg-curves")]
        if fit is None:
            parts.append(page.paragraph("No published analytic fit of this table's convention is known to pbrfit ("
                                        f"{string_attribute(group.node, 'visibility')}; "
                                        f"{string_attribute(group.node, 'roughness_parametrization')})."))
        else:
            parts.append(page.paragraph(f"Beside {fit_name}, the published analytic fit of this convention "
                                        f"({string_attribute(group.node, 'visibility')}; "
                                        f"{string_attribute(group.node, 'roughness_parametrization')}), over every "
                                        "cell of the table:"))
            parts.append(page.table(["", "RMS difference", "95th percentile", "largest", "where"],
                                    _fit_rows(n_dot_v, roughness, scale, bias, fit), (1, 2, 3)))
        name = report.figures.draw(lambda: curves_figure(n_dot_v, roughness, axis_name, scale, bias, fit, fit_name))
        if name:
            parts.append(page.image_figure(name, "dfg scale and bias curves",
                                           f"dfg/scale and dfg/bias over n_dot_v at {axis_name} near "
                                           f"{', '.join(str(p) for p in ROUGHNESS_PICKS)}"))
        for table in group.tables:
            table.forget_values()
        return [page.section(parts)]
