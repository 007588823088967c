# The run summary at the top of every report: the root attributes as a table (the ones every pbrfit
# result has, in the order of store/result_file.hpp, then any others by name) and the job text as
# written, preformatted.
from . import html_page as page
from .attributes import attribute_texts, string_attribute

KNOWN_ORDER = ("job_name", "job_kind", "state", "headline", "items_done", "items_total", "elapsed_seconds",
               "started_utc", "finished_utc", "updated_utc", "seed", "ranks", "threads", "scheduler_job",
               "writer_host", "writer_pid", "pbrfit_version")
JOB_TEXT = "job_yaml"


def _ordered(texts):
    by_name = dict(texts)
    known = [(n, by_name[n]) for n in KNOWN_ORDER if n in by_name]
    rest = [(n, v) for n, v in texts if n not in KNOWN_ORDER and n != JOB_TEXT]
    return known + rest


def run_summary_markup(file, result_path):
    rows = [["result file", result_path]] + [[n, v] for n, v in _ordered(attribute_texts(file))]
    return page.section([page.heading(2, "Run", "run"), page.table(["attribute", "value"], rows),
                         page.heading(3, "Job file"), page.preformatted(string_attribute(file, JOB_TEXT))])
