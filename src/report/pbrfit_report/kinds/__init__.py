# Renderers by job kind (the root attribute job_kind): a kind registers a generic.Renderer subclass with
# @register("KIND") in a module of this folder, imported below; renderer_for() of any other kind, or of
# a file without one, is the generic Renderer.
from ..generic import Renderer

_RENDERERS = {}


def register(kind):
    def add(renderer_class):
        _RENDERERS[kind] = renderer_class
        return renderer_class
    return add


def renderer_for(kind):
    return _RENDERERS.get(kind, Renderer)()


from . import lut  # noqa: E402,F401 - registers itself
from . import symreg  # noqa: E402,F401 - registers itself
from . import brdf_search  # noqa: E402,F401 - registers itself
from . import ebrdf  # noqa: E402,F401 - registers itself
from . import sweep  # noqa: E402,F401 - registers itself
