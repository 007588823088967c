#!/usr/bin/env bash
# Started by mpirun in place of pbrfit (start_ranks): appends "RANK PID" to $RANK_PIDS_FILE, then becomes
# pbrfit under the same pid. The tests signal ranks by the pids the ranks reported themselves, so they need
# neither /proc nor session membership to find them. With $RANK_LOG set, the rank appends its output to
# that file itself instead of handing it to mpirun, whose forwarding can deliver it seconds late.
echo "${OMPI_COMM_WORLD_RANK:?not started by mpirun} $$" >>"${RANK_PIDS_FILE:?}"
[[ -z ${RANK_LOG:-} ]] || exec "${PBRFIT:?}" "$@" >>"$RANK_LOG" 2>&1
exec "${PBRFIT:?}" "$@"
