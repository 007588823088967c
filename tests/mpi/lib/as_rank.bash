#!/usr/bin/env bash
# Started by mpirun in place of pbrfit (start_ranks): appends "RANK PID" to $RANK_PIDS_FILE, then becomes
# pbrfit under the same pid. The tests signal ranks by the pids the ranks reported themselves, so they need
# neither /proc nor session membership to find them.
echo "${OMPI_COMM_WORLD_RANK:?not started by mpirun} $$" >>"${RANK_PIDS_FILE:?}"
exec "${PBRFIT:?}" "$@"
