# `pbrfit report RESULT.h5 [--out DIR]`, the Python side: writes DIR/index.html and its figures, prints
# one line saying where, and returns the exit code: 0, 2 (the result cannot be read: "FILE: error: ..."),
# 3 (the report cannot be made: "pbrfit: error: ..."). Whatever happens, at most one line goes to stderr:
# library warnings are silenced and everything raised becomes that line, never a traceback.
import argparse
import contextlib
import io
import os
import sys
import warnings

from .problems import EXIT_INVALID_INPUT, EXIT_RUN_FAILURE, EXIT_SUCCESS, InputProblem, RunProblem, one_line


class _Arguments(argparse.ArgumentParser):
    def error(self, message):
        raise RunProblem(f"report: {message}")


def _parse(argv):
    parser = _Arguments(prog="pbrfit report", add_help=False)
    parser.add_argument("result")
    parser.add_argument("--out", default="")
    return parser.parse_args(argv)


def _make_report(result_path, out):
    os.environ.setdefault("MPLBACKEND", "Agg")
    import matplotlib
    matplotlib.use("Agg")
    from . import report_directory  # imported here: a missing library is reported by _run, in one line
    from .attributes import string_attribute
    from .figures import FigureWriter
    from .generic import Report
    from .html_page import document
    from .kinds import renderer_for
    from .result_input import open_result
    from .result_tree import walk

    directory = out or report_directory.default_directory(result_path)
    with open_result(result_path) as file:
        report_directory.create(directory)
        report = Report(file, result_path, walk(file), FigureWriter(directory))
        parts = renderer_for(string_attribute(file, "job_kind")).render(report)
        title = "pbrfit report: " + string_attribute(file, "job_name", "?")
        index = report_directory.write_index(directory, document(title, parts))
    report.figures.remove_stale()
    return index, len(report.figures.written)


def _run(argv):
    args = _parse(argv)
    try:
        return _make_report(args.result, args.out)
    except (InputProblem, RunProblem):
        raise
    except ImportError as error:
        raise RunProblem(f"the report needs h5py, numpy and matplotlib for {sys.executable} "
                         f"(Debian: python3-h5py python3-matplotlib): {error}") from error
    except MemoryError as error:
        raise RunProblem(f"out of memory while making the report of {args.result}") from error
    except Exception as error:  # noqa: BLE001 - any other failure is one line, exit 3
        raise RunProblem(f"cannot make the report of {args.result}: {type(error).__name__}: {error}") from error


def main(argv):
    warnings.simplefilter("ignore")
    captured = io.StringIO()
    try:
        with contextlib.redirect_stderr(captured):
            index, figures = _run(argv)
    except InputProblem as problem:
        print(problem.line(), file=sys.stderr)
        return EXIT_INVALID_INPUT
    except RunProblem as problem:
        print(problem.line(), file=sys.stderr)
        return EXIT_RUN_FAILURE
    except KeyboardInterrupt:
        print("pbrfit: error: report interrupted", file=sys.stderr)
        return EXIT_RUN_FAILURE
    print(one_line(f"report: {index} ({figures} figure{'s' if figures != 1 else ''})"))
    return EXIT_SUCCESS
