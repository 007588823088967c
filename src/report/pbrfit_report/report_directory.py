# The report directory: created when missing (parents too); index.html replaced atomically (written
# beside it, then renamed), so a reader sees the old page or the new one; figures of an earlier report
# that this one did not write are removed after the new page is in place. Failures are RunProblems
# naming the path and the OS's reason.
import os

from .problems import RunProblem


def default_directory(result_path):
    """RESULT.h5 -> RESULT.report; a path without .h5 gets .report appended."""
    stem = result_path[:-3] if result_path.endswith(".h5") else result_path
    return stem + ".report"


def create(directory):
    try:
        os.makedirs(directory, exist_ok=True)
    except OSError as error:
        raise RunProblem(f"cannot create report directory {directory}: {error.strerror or error}") from error


def write_index(directory, markup):
    path = os.path.join(directory, "index.html")
    temporary = path + ".tmp"
    try:
        with open(temporary, "w", encoding="utf-8", errors="surrogateescape") as out:
            out.write(markup)
        os.replace(temporary, path)
    except OSError as error:
        try:
            os.remove(temporary)
        except OSError:
            pass
        raise RunProblem(f"cannot write {path}: {error.strerror or error}") from error
    return path
