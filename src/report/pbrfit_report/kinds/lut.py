# `lut` results (docs/results-lut.md): reference tables over two axes; the generic report already shows
# each table as a map with its summary, so this kind adds no section of its own yet.
from ..generic import Renderer
from . import register


@register("lut")
class LutRenderer(Renderer):
    pass
