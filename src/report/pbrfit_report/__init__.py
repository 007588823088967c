# pbrfit_report: the HTML report of one pbrfit result file (`pbrfit report`). Reads the file read-only
# with h5py, draws PNG figures with matplotlib's Agg backend and writes DIR/index.html; nothing else.
