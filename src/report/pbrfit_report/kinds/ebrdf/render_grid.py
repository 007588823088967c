# One scene's renders side by side: a row per camera distance, columns ground truth, naive, ours, each
# titled with its MSE against the ground truth.
import numpy as np

from ...figure_parts import new_figure

TILE_INCHES = 1.8
METHODS = ("ground truth", "naive", "ours")


def render_grid(renders, distances, texels, mse):
    """renders: u8 [distance, method, row, column, channel]; mse: [distance, (naive, ours)]."""
    rows = len(distances)
    figure = new_figure(TILE_INCHES * 3 + 0.6, TILE_INCHES * rows + 0.3)
    for d in range(rows):
        for m in range(3):
            ax = figure.add_subplot(rows, 3, d * 3 + m + 1)
            ax.imshow(np.asarray(renders[d, m]), interpolation="nearest")
            ax.set_xticks([])
            ax.set_yticks([])
            title = METHODS[m] if m == 0 else f"{METHODS[m]}, MSE {mse[d, m - 1]:.2g}"
            ax.set_title(title, fontsize=7)
            if m == 0:
                ax.set_ylabel(f"h {distances[d]:g}, {texels[d]:.2g} t/px", fontsize=7)
    figure.tight_layout(pad=0.3)
    return figure
