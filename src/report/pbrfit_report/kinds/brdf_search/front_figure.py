# The genBRDF front: the search's error (sqrt S', summed over the training materials) over tree size on a
# log axis, the staircase of the front, the knee ringed and the seed's size marked.
from ...figure_parts import new_figure, title


def brdf_front_figure(front, seed_size):
    figure = new_figure(7.0, 4.2)
    ax = figure.add_subplot()
    ax.plot(front["cost"], front["rmse"], drawstyle="steps-post", marker="o", markersize=4, linewidth=1)
    knee = [k for k, v in enumerate(front["knee"]) if v == 1]
    if knee:
        ax.plot([front["cost"][knee[0]]], [front["rmse"][knee[0]]], marker="o", markersize=13, markerfacecolor="none",
                markeredgewidth=2, color="#d62728", linestyle="none", label="knee")
    if seed_size is not None:
        ax.axvline(seed_size, color="#7f7f7f", linestyle="--", linewidth=1, label="the seed's size")
    ax.set_yscale("log")
    ax.set_xlabel("syntax tree size (nodes)")
    ax.set_ylabel("error on the training materials")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    title(ax, f"brdf/front: {len(front)} members, error vs size")
    return figure
