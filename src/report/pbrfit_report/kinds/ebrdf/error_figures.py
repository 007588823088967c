# Line plots of the eBRDF report: fit error by mip level per component, and the renders' MSE against the
# ground truth and their energy relative to it, by texels per pixel per scene and method.
import numpy as np

from ...figure_parts import new_figure


def level_error_figure(rows):
    """rows: component -> [(level, shape, finite errors)]."""
    figure = new_figure(5.0, 3.2)
    ax = figure.add_subplot()
    for component, levels in rows.items():
        points = [(level, e.mean()) for level, _, e in levels if e.size]
        if points:
            ax.plot(*zip(*points), marker="o", label=component)
    ax.set_xlabel("mip level")
    ax.set_ylabel("mean sliced Wasserstein error")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    figure.tight_layout()
    return figure


def mse_figure(scenes, texels, mse):
    figure = new_figure(5.6, 3.4)
    ax = figure.add_subplot()
    for s, scene in enumerate(scenes):
        done = np.isfinite(mse[s, :, 0])
        ax.plot(texels[s, done], mse[s, done, 0], marker="s", linestyle="--", label=f"{scene}: naive")
        ax.plot(texels[s, done], mse[s, done, 1], marker="o", label=f"{scene}: ours")
    ax.axvline(2.0, color="grey", linewidth=0.8)
    ax.set_xscale("log")
    ax.set_xlabel("texels per pixel (image centre)")
    ax.set_ylabel("MSE against the ground truth")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    figure.tight_layout()
    return figure


def energy_figure(scenes, texels, energy, highlight):
    """energy, highlight: [scene, distance, (ground truth, naive, ours)] mean linear radiance."""
    figure = new_figure(7.6, 3.4)
    for i, (values, title) in enumerate(((energy, "whole plane"), (highlight, "highlight"))):
        ax = figure.add_subplot(1, 2, i + 1)
        for s, scene in enumerate(scenes):
            done = np.isfinite(values[s, :, 0]) & (values[s, :, 0] > 0)
            ax.plot(texels[s, done], values[s, done, 1] / values[s, done, 0], marker="s", linestyle="--",
                    label=f"{scene}: naive")
            ax.plot(texels[s, done], values[s, done, 2] / values[s, done, 0], marker="o", label=f"{scene}: ours")
        ax.axhspan(0.95, 1.05, color="grey", alpha=0.15)
        ax.axvline(2.0, color="grey", linewidth=0.8)
        ax.set_xscale("log")
        ax.set_xlabel("texels per pixel (image centre)")
        ax.set_ylabel(f"energy / ground truth ({title})")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
    figure.tight_layout()
    return figure
