# The fitted LTC lobe beside its target, in the plane of incidence, at a few cells of a GGX table (as the
# LTC paper's figures show them): the target is GGX with height-correlated Smith masking, F = 1, times
# the cosine, rho(l) = D(h) G2(v, l) / (4 n.v) with alpha = r^2; the LTC is norm x D_o(M^-1 l / |M^-1 l|)
# |det M^-1| / |M^-1 l|^3 with D_o the clamped cosine over pi, M the cell's `matrix` (docs/results-sweep.md).
# Each panel is scaled to its target's peak; the light's angle runs from -90 to 90 degrees (the view at
# positive angles, mirrored at negative ones).
import numpy as np

from ...figure_parts import new_figure

GGX_MODELS = ("ltc", "ggx")  # ltc_ggx's model and the ggx family of problem ltc: alpha = r^2
ROUGHNESS_PICKS = (0.25, 0.5, 0.8)
VIEW_PICKS_DEGREES = (30.0, 70.0)


def ggx_target(alpha, cos_view, theta_light):
    """rho(l) (n.l) for lights at the angles theta_light (radians, in the plane of incidence)."""
    alpha = max(alpha, 1e-5)
    v = np.array([np.sqrt(max(0.0, 1 - cos_view ** 2)), 0.0, cos_view])
    l = np.stack([np.sin(theta_light), np.zeros_like(theta_light), np.cos(theta_light)], axis=-1)
    h = l + v
    h /= np.linalg.norm(h, axis=-1, keepdims=True)
    a2 = alpha * alpha
    d = a2 / (np.pi * ((h[:, 2] ** 2) * (a2 - 1) + 1) ** 2)

    def smith_lambda(cos_theta):
        cos_theta = np.clip(cos_theta, 1e-9, 1.0)
        tan2 = (1 - cos_theta ** 2) / cos_theta ** 2
        return (-1 + np.sqrt(1 + a2 * tan2)) / 2

    g2 = 1 / (1 + smith_lambda(np.full_like(theta_light, cos_view)) + smith_lambda(l[:, 2]))
    return np.where(l[:, 2] > 0, d * g2 / (4 * cos_view), 0.0)


def ltc_lobe(matrix, norm, theta_light):
    """norm x the LTC's distribution at lights in the plane of incidence; matrix is M, 3 x 3."""
    inverse = np.linalg.inv(matrix)
    l = np.stack([np.sin(theta_light), np.zeros_like(theta_light), np.cos(theta_light)], axis=-1)
    local = l @ inverse.T
    length = np.linalg.norm(local, axis=-1)
    cosine = np.maximum(local[:, 2] / length, 0.0) / np.pi
    return norm * cosine * abs(np.linalg.det(inverse)) / length ** 3


def lobe_cells(roughness, view_x):
    """(roughness index, view index) of the picked cells: the nearest grid points to the picks."""
    cos_theta = np.cos(np.minimum(np.arccos(np.clip(1 - view_x ** 2, -1, 1)), 1.57))
    view_degrees = np.degrees(np.arccos(cos_theta))
    cells = []
    for v in VIEW_PICKS_DEGREES:
        for r in ROUGHNESS_PICKS:
            cell = (int(np.argmin(np.abs(roughness - r))), int(np.argmin(np.abs(view_degrees - v))))
            if cell not in cells:
                cells.append(cell)
    return cells, cos_theta


def lobe_figure(matrix, norm, roughness, view_x):
    """matrix[view, roughness, 9] and norm[view, roughness] over the two axes."""
    cells, cos_theta = lobe_cells(roughness, view_x)
    theta = np.linspace(-np.pi / 2, np.pi / 2, 721)
    columns = len(ROUGHNESS_PICKS)
    rows = (len(cells) + columns - 1) // columns
    figure = new_figure(3.0 * columns, 2.6 * rows)
    for k, (ri, vi) in enumerate(cells):
        ax = figure.add_subplot(rows, columns, k + 1, projection="polar")
        ax.set_theta_zero_location("N")
        ax.set_thetamin(-90)
        ax.set_thetamax(90)
        target = ggx_target(roughness[ri] ** 2, cos_theta[vi], theta)
        peak = target.max() if np.isfinite(target).all() and target.max() > 0 else 1.0
        m = matrix[vi, ri].reshape(3, 3)
        ax.plot(theta, target / peak, color="black", linewidth=1.5, label="GGX")
        if np.isfinite(m).all() and np.isfinite(norm[vi, ri]):
            ax.plot(theta, ltc_lobe(m, norm[vi, ri], theta) / peak, color="tab:orange", linestyle="--",
                    linewidth=1.5, label="LTC")
        ax.set_rmax(1.1)
        ax.set_yticklabels([])
        ax.set_title(f"r = {roughness[ri]:.2f}, view {np.degrees(np.arccos(cos_theta[vi])):.0f} deg", fontsize=9)
        if k == 0:
            ax.legend(loc="lower left", fontsize=8, bbox_to_anchor=(-0.15, -0.15))
    return figure


def is_lobes_group(group):
    names = {t.name for t in group.tables}
    return group.path.endswith("/lobes") and {"target", "ltc"} <= names


def file_lobe_figure(group):
    """The lobes the job computed (`<model>/lobes`, any BRDF): a column per image's roughness, a row per view;
    target solid, the table dashed, the published table dotted, each panel scaled to its target's peak."""
    node = group.node
    target, ours = node["target"][()], node["ltc"][()]
    published = node["published"][()] if "published" in node else None
    if published is not None and not np.isfinite(published).any():
        published = None
    image_axis = next(a for a in group.axes if a.name not in ("view_degrees", "light_degrees"))
    views, angles = node["view_degrees"][()], np.radians(node["light_degrees"][()])
    columns, rows = target.shape[0], target.shape[1]
    figure = new_figure(3.0 * columns, 2.6 * rows)
    for v in range(rows):
        for i in range(columns):
            ax = figure.add_subplot(rows, columns, v * columns + i + 1, projection="polar")
            ax.set_theta_zero_location("N")
            ax.set_thetamin(-90)
            ax.set_thetamax(90)
            finite = target[i, v][np.isfinite(target[i, v])]
            peak = finite.max() if finite.size and finite.max() > 0 else 1.0
            ax.plot(angles, target[i, v] / peak, color="black", linewidth=1.5, label="target")
            ax.plot(angles, ours[i, v] / peak, color="tab:orange", linestyle="--", linewidth=1.5, label="this table")
            if published is not None and np.isfinite(published[i, v]).any():
                ax.plot(angles, published[i, v] / peak, color="tab:blue", linestyle=":", linewidth=1.5,
                        label="published")
            ax.set_rmax(1.1)
            ax.set_yticklabels([])
            ax.set_title(f"{image_axis.name} {image_axis.values[i]:.2f}, view {views[v]:.0f} deg", fontsize=9)
            if v == 0 and i == 0:
                ax.legend(loc="lower left", fontsize=8, bbox_to_anchor=(-0.15, -0.2))
    return figure
