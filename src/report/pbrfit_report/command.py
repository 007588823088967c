# `pbrfit report RESULT.h5 [--out DIR] [--watch SECONDS]`, the Python side: writes DIR/index.html and its
# figures, prints one line saying where, and returns the exit code: 0, 2 (the result cannot be read: "FILE:
# error: ..."), 3 (the report cannot be made: "pbrfit: error: ..."). Whatever happens, at most one line goes
# to stderr: library warnings are silenced and everything raised becomes that line, never a traceback.
# With --watch, while the job's state is `running` the report is made again every SECONDS (a line each
# time) and the page reloads itself at that interval; the last report, once the job has stopped, does not.
import argparse
import contextlib
import io
import os
import sys
import time
import warnings

from .problems import EXIT_INVALID_INPUT, EXIT_RUN_FAILURE, EXIT_SUCCESS, InputProblem, RunProblem, one_line


class _Arguments(argparse.ArgumentParser):
    def error(self, message):
        raise RunProblem(f"report: {message}")


def _parse(argv):
    parser = _Arguments(prog="pbrfit report", add_help=False)
    parser.add_argument("result")
    parser.add_argument("--out", default="")
    parser.add_argument("--watch", type=float, default=0.0)
    return parser.parse_args(argv)


def _make_report(result_path, out, watch=0.0):
    """(index path, figures written, the job's state)."""
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
        state = string_attribute(file, "state")
        refresh = watch if watch > 0 and state == "running" else 0
        index = report_directory.write_index(directory, document(title, parts, refresh))
    report.figures.remove_stale()
    return index, len(report.figures.written), state


def _run(args):
    try:
        return _make_report(args.result, args.out, args.watch)
    except (InputProblem, RunProblem):
        raise
    except ImportError as error:
        raise RunProblem(f"the report needs h5py, numpy and matplotlib for {sys.executable} "
                         f"(Debian: python3-h5py python3-matplotlib): {error}") from error
    except MemoryError as error:
        raise RunProblem(f"out of memory while making the report of {args.result}") from error
    except Exception as error:  # noqa: BLE001 - any other failure is one line, exit 3
        raise RunProblem(f"cannot make the report of {args.result}: {type(error).__name__}: {error}") from error


def _report_line(index, figures, state, watch):
    line = f"report: {index} ({figures} figure{'s' if figures != 1 else ''})"
    return line + (f"; the job is running, again in {watch:g} s" if watch > 0 and state == "running" else "")


def main(argv):
    warnings.simplefilter("ignore")
    captured = io.StringIO()
    try:
        with contextlib.redirect_stderr(captured):
            args = _parse(argv)
            while True:
                index, figures, state = _run(args)
                if args.watch <= 0 or state != "running":
                    break
                print(one_line(_report_line(index, figures, state, args.watch)), flush=True)
                time.sleep(args.watch)
    except InputProblem as problem:
        print(problem.line(), file=sys.stderr)
        return EXIT_INVALID_INPUT
    except RunProblem as problem:
        print(problem.line(), file=sys.stderr)
        return EXIT_RUN_FAILURE
    except KeyboardInterrupt:
        print("pbrfit: error: report interrupted", file=sys.stderr)
        return EXIT_RUN_FAILURE
    print(one_line(_report_line(index, figures, state, 0)))
    return EXIT_SUCCESS
