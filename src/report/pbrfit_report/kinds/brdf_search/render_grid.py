# The evaluation's renders side by side (docs/results-brdf_search.md): a row per material (training, then
# testing), a column per image (the measured render, then each fitted model), each tile titled with the
# model and its image L2 and 1 - SSIM. Rows past MAX_ROWS are left out and the caption says so.
import numpy as np

from ...figure_parts import new_figure

MAX_ROWS = 24
TILE_INCHES = 1.6


def render_grid(renders, materials, images, errors):
    """renders: u8 [material, image, row, column, channel]; errors[(m, i)] -> (l2, 1 - ssim) for i >= 1."""
    rows, columns = min(len(materials), MAX_ROWS), len(images)
    figure = new_figure(TILE_INCHES * columns + 1.2, TILE_INCHES * rows + 0.4)
    for m in range(rows):
        for i in range(columns):
            ax = figure.add_subplot(rows, columns, m * columns + i + 1)
            ax.imshow(np.asarray(renders[m, i]), interpolation="nearest")
            ax.set_xticks([])
            ax.set_yticks([])
            title = images[i] if i == 0 else f"{images[i]}\nL2 {errors[(m, i)][0]:.3g}, 1-SSIM {errors[(m, i)][1]:.3g}"
            ax.set_title(title, fontsize=6)
            if i == 0:
                ax.set_ylabel(materials[m], fontsize=7)
    figure.tight_layout(pad=0.3)
    return figure
