# Writes a synthetic pbrfit result (Debian's h5py: run with /usr/bin/python3) with what kinds beyond
# `lut` will write: a 3-D and a 4-D table, tables with roles (parameter, error, anchor_error, start,
# count), NaNs of a run in progress, a nested group, a growing record table of 250 rows and a text table
# holding HTML special characters and a newline. Usage: synthetic_result.py OUT.h5
import sys

import h5py
import numpy as np

SPECIAL_TEXT = '<b>bold</b> & "quoted" \'single\'\nsecond line'


def axis(group, name, values, description):
    data = group.create_dataset(name, data=np.asarray(values, dtype=np.float64))
    data.make_scale(name)
    data.attrs["description"] = description
    return data


def table(group, name, values, axes, description, role=None, **attributes):
    data = group.create_dataset(name, data=values, maxshape=(None,) + values.shape[1:], chunks=True)
    for d, a in enumerate(axes):
        data.dims[d].attach_scale(a)
    data.attrs["description"] = description
    data.attrs["axes"] = ", ".join(a.name.rsplit("/", 1)[-1] for a in axes)
    if role:
        data.attrs["role"] = role
    for key, value in attributes.items():
        data.attrs[key] = value
    return data


def root_attributes(f):
    for key, value in {"pbrfit_version": "0.1.0", "job_name": "synthetic <fit> & co", "job_kind": "synthetic",
                       "job_yaml": "name: synthetic\nkind: synthetic  # <script>alert(1)</script>\n",
                       "state": "running", "started_utc": "2025-01-01T00:00:00Z", "finished_utc": "",
                       "headline": "mean error 1e-3 <vs> 2e-3", "updated_utc": "2025-01-01T00:01:00Z",
                       "writer_host": "nowhere", "scheduler_job": ""}.items():
        f.attrs[key] = value
    for key, value in {"seed": 7, "items_done": 5, "items_total": 9, "ranks": 2, "threads": 1,
                       "writer_pid": 0}.items():
        f.attrs[key] = np.int64(value)
    f.attrs["elapsed_seconds"] = 12.5


def fit_group(f, rng):
    g = f.create_group("fit")
    g.attrs["description"] = "an isotropic fit, <in progress>"
    g.attrs["model"] = "ltc & friends"
    theta = axis(g, "theta", np.linspace(0.0, 1.5, 8), "view angle in radians")
    rough = axis(g, "roughness", np.geomspace(0.01, 1.0, 6), "GGX alpha (not evenly spaced)")
    aniso = axis(g, "anisotropy", [0.0, 0.5, 0.9], "anisotropy")
    params = rng.random((3, 6, 8))
    params[2, 3:, :] = np.nan
    table(g, "params", params, [aniso, rough, theta], "fitted m00", "parameter")
    error = 10.0 ** rng.uniform(-6, -1, (6, 8))
    error[5, 4:] = np.nan
    table(g, "error", error, [rough, theta], "our fit error", "error")
    anchor = error * rng.uniform(0.3, 3.0, (6, 8))
    anchor[0, 0] = np.nan
    anchor[1, :3] = error[1, :3]  # ties: ours <= the anchor's counts them, ours < would not
    table(g, "heitz_error", anchor, [rough, theta], "error of the published table", "anchor_error",
          anchor="Heitz et al. 2016", compares_with="error")
    table(g, "start", rng.integers(0, 3, (6, 8)).astype(np.int32), [rough, theta], "winning start", "start",
          labels="0=cold,1=parent,2=neighbour")
    table(g, "evaluations", rng.integers(10, 100000, (6, 8)).astype(np.int64), [rough, theta], "evaluations",
          "count")
    return g, theta


def nested_group(g):
    level = g.create_group("level2")
    level.attrs["description"] = "a finer level"
    t2 = axis(level, "t2", np.linspace(0, 1, 16), "finer parameter")
    a, b = axis(level, "a", [1.0, 2.0], "outer a"), axis(level, "b", [0.1, 0.2, 0.3], "outer b")
    curve = np.sin(np.linspace(0, 3, 16)).astype(np.float32)
    curve[-3:] = np.nan
    table(level, "curve", curve, [t2], "a curve in float32")
    table(level, "cube4", np.arange(2 * 3 * 16 * 16, dtype=np.float64).reshape(2, 3, 16, 16), [a, b, t2, t2],
          "a 4-D table")


def growing_tables(g):
    record = np.dtype([("size", np.int32), ("error", np.float64), ("expression", h5py.string_dtype())])
    rows = np.array([(i, 1.0 / (i + 1), f"x * {i} < y & z") for i in range(250)], dtype=record)
    front = g.create_dataset("front", data=rows, maxshape=(None,), chunks=True)
    front.attrs["description"] = "Pareto front members"
    front.attrs["axes"] = "member"
    front.attrs["field_size"] = "program length"
    front.attrs["field_expression"] = "the program <as text>"
    notes = g.create_dataset("notes", data=np.array([SPECIAL_TEXT, "plain"], dtype=object),
                             dtype=h5py.string_dtype(), maxshape=(None,), chunks=True)
    notes.attrs["description"] = "free text"
    notes.attrs["axes"] = "note"


def main(path):
    rng = np.random.default_rng(1)
    with h5py.File(path, "w") as f:
        root_attributes(f)
        g, _ = fit_group(f, rng)
        nested_group(g)
        growing_tables(g)


if __name__ == "__main__":
    main(sys.argv[1])
