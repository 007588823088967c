#!/usr/bin/env bash
# Stop a cluster started by cluster/local-slurm/start.sh.
#
# Usage:  cluster/local-slurm/stop.sh [--clean] STATE_DIR
#
# 1. If its slurmctld still answers, cancels this cluster's jobs and waits (bounded) for them.
# 2. Sends TERM to the daemons listed in STATE_DIR/pids (slurmd, slurmctld, munged), by PID,
#    waits up to LOCAL_SLURM_STOP_TIMEOUT (15) s, then KILLs the ones still alive.
# 3. Stops any slurmstepd left by this slurmd (one with a file under STATE_DIR open) and the
#    processes below it (the step's tasks).
# --clean then removes STATE_DIR. Never signals processes by name. Exit 0 when nothing of this
# cluster is left running (also when it was not running at all).
set -euo pipefail

log() { echo "local-slurm: $*" >&2; }
die() { log "error: $*"; exit 1; }

clean=0
state=
for a in "$@"; do
  case "$a" in
    --clean) clean=1 ;;
    -h|--help) sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | sed '$d; s/^# \{0,1\}//' >&2; exit 0 ;;
    -*) die "unknown option $a" ;;
    *) [[ -z $state ]] || die "usage: stop.sh [--clean] STATE_DIR"; state=$a ;;
  esac
done
[[ -n $state ]] || die "usage: stop.sh [--clean] STATE_DIR"
if [[ ! -d $state ]]; then log "$state does not exist; nothing to stop"; exit 0; fi
state=$(cd "$state" && pwd -P)
PATH=$PATH:/usr/sbin
timeout_s=${LOCAL_SLURM_STOP_TIMEOUT:-15}

alive() { [[ -d /proc/$1 ]] && ! grep -q '^State:.*Z' "/proc/$1/status" 2>/dev/null; }

# Is PID still the daemon NAME we started (guards against PID reuse)?
is_ours() {
  local pid=$1 name=$2 comm
  alive "$pid" || return 1
  comm=$(cat "/proc/$pid/comm" 2>/dev/null) || return 1
  [[ $comm == "$name" ]]
}

# terminate SECONDS PID...: TERM the PIDs, wait up to SECONDS, KILL the rest, wait a little more.
terminate() {
  local wait_s=$1 pid left deadline
  shift
  [[ $# -gt 0 ]] || return 0
  kill -TERM "$@" 2>/dev/null || true
  deadline=$((SECONDS + wait_s))
  while :; do
    left=()
    for pid in "$@"; do alive "$pid" && left+=("$pid"); done
    [[ ${#left[@]} -eq 0 ]] && return 0
    ((SECONDS < deadline)) || break
    sleep 0.2
  done
  log "still alive after ${wait_s} s, sending KILL: ${left[*]}"
  kill -KILL "${left[@]}" 2>/dev/null || true
  deadline=$((SECONDS + 5))
  while ((SECONDS < deadline)); do
    left=()
    for pid in "$@"; do alive "$pid" && left+=("$pid"); done
    [[ ${#left[@]} -eq 0 ]] && return 0
    sleep 0.2
  done
  log "could not kill: ${left[*]}"
  return 1
}

declare -A pid_of=()
if [[ -s $state/pids ]]; then
  while read -r name pid; do
    [[ -n ${name:-} && ${pid:-} =~ ^[0-9]+$ ]] && pid_of[$name]=$pid
  done <"$state/pids"
fi

# 1. Cancel this cluster's jobs while slurmctld and slurmd still run, so steps end cleanly.
if [[ -n ${pid_of[slurmctld]:-} ]] && is_ours "${pid_of[slurmctld]}" slurmctld && [[ -f $state/slurm.conf ]]; then
  export SLURM_CONF=$state/slurm.conf
  jobs=$(timeout 10 squeue -h -o %A 2>/dev/null || true)
  if [[ -n $jobs ]]; then
    log "cancelling jobs: ${jobs//$'\n'/ }"
    # shellcheck disable=SC2086
    timeout 10 scancel $jobs 2>/dev/null || true
    deadline=$((SECONDS + timeout_s + 5))
    while [[ -n $(timeout 10 squeue -h -t R,CG,S -o %A 2>/dev/null || true) ]] && ((SECONDS < deadline)); do
      sleep 0.5
    done
  fi
fi

# 2. The daemons start.sh recorded, compute side first.
rc=0
for name in slurmd slurmctld munged; do
  pid=${pid_of[$name]:-}
  [[ -n $pid ]] || continue
  if is_ours "$pid" "$name"; then
    log "stopping $name (pid $pid)"
    terminate "$timeout_s" "$pid" || rc=1
  fi
done

# 3. Leftover slurmstepd of this slurmd (they outlive slurmd by design) and their step's tasks.
#    A slurmstepd is ours when it has a file under STATE_DIR open (it logs to
#    STATE_DIR/log/slurmd.log); its tasks are its descendants.
descendants() {
  local c
  # shellcheck disable=SC2013  # the file is one line of space-separated PIDs
  for c in $(cat "/proc/$1/task/"*/children 2>/dev/null); do
    echo "$c"
    descendants "$c"
  done
}
strays=()
for dir in /proc/[0-9]*; do
  pid=${dir#/proc/}
  [[ $(cat "$dir/comm" 2>/dev/null) == slurmstepd ]] || continue
  alive "$pid" || continue
  if find "$dir/fd" -mindepth 1 -maxdepth 1 -lname "$state/*" -print -quit 2>/dev/null | grep -q .; then
    read -r -a tree <<<"$(descendants "$pid" | tr '\n' ' ')"
    strays+=("$pid" "${tree[@]}")
  fi
done
if [[ ${#strays[@]} -gt 0 ]]; then
  log "stopping leftover step processes: ${strays[*]}"
  terminate 5 "${strays[@]}" || rc=1   # slurmstepd ignores TERM: short wait, then KILL
fi

if [[ $rc -eq 0 ]]; then
  rm -f "$state/pids"
  log "stopped ($state)"
else
  log "some processes could not be stopped; $state/pids kept"
fi

if [[ $clean -eq 1 && $rc -eq 0 ]]; then
  # Only remove what looks like our state dir.
  if [[ -f $state/slurm.conf && -d $state/munge && $state != / ]]; then
    rm -rf -- "$state"
    log "removed $state"
  else
    log "not removing $state: does not look like a local-slurm state dir"
  fi
fi
exit "$rc"
