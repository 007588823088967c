# Opening the result read-only, as `pbrfit status` would accept it: a regular readable file, an HDF5
# file, with the root attributes pbrfit_version and job_yaml. Anything else is an InputProblem naming the
# file. The writer publishes complete copies by rename, so a file open here stays consistent while the
# job runs.
import os
import stat

import h5py

from .problems import InputProblem


def _check_regular(path):
    try:
        mode = os.stat(path).st_mode
    except OSError as error:
        raise InputProblem(path, f"cannot read file: {error.strerror}") from error
    if stat.S_ISDIR(mode):
        raise InputProblem(path, "is a directory, not a file")
    if not stat.S_ISREG(mode):
        raise InputProblem(path, "is not a regular file")
    if not os.access(path, os.R_OK):
        raise InputProblem(path, "cannot read file: Permission denied")


def open_result(path):
    _check_regular(path)
    try:
        file = h5py.File(path, "r")
    except OSError as error:
        raise InputProblem(path, "not a readable HDF5 file (damaged, or not a pbrfit result)") from error
    if "pbrfit_version" not in file.attrs or "job_yaml" not in file.attrs:
        file.close()
        raise InputProblem(path, "not a pbrfit result file (no pbrfit_version or job_yaml attribute)")
    return file
