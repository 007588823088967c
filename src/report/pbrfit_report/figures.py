# Where figures go: PNG files fig-0001.png, fig-0002.png, ... in the report directory, at most `limit`
# of them. draw() asks for a figure only while there is room; past the limit it counts what it left out
# (the page says so). File names never come from the result file. A figure that cannot be written is a
# RunProblem naming the file.
import os
import re

from .problems import RunProblem

MAX_FIGURES = 200
DPI = 80
FIGURE_NAME = re.compile(r"fig-\d{4,}\.png\Z")


class FigureWriter:
    def __init__(self, directory, limit=MAX_FIGURES):
        self.directory = directory
        self.limit = limit
        self.written = []
        self.left_out = 0

    def draw(self, make_figure):
        """make_figure() -> matplotlib Figure, called only while there is room; returns the file name
        relative to the report directory, or None when the limit left the figure out."""
        if len(self.written) >= self.limit:
            self.left_out += 1
            return None
        figure = make_figure()
        name = f"fig-{len(self.written) + 1:04d}.png"
        path = os.path.join(self.directory, name)
        try:
            figure.savefig(path, dpi=DPI)
        except OSError as error:
            raise RunProblem(f"cannot write {path}: {error.strerror or error}") from error
        self.written.append(name)
        return name

    def remove_stale(self):
        """Removes figures of an earlier report in the same directory that this one did not write."""
        keep = set(self.written)
        for name in os.listdir(self.directory):
            if FIGURE_NAME.match(name) and name not in keep:
                try:
                    os.remove(os.path.join(self.directory, name))
                except OSError:
                    pass
