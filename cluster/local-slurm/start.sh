#!/usr/bin/env bash
# Start a private single-node Slurm cluster (munged + slurmctld + slurmd) on 127.0.0.1.
#
# Usage:  eval "$(cluster/local-slurm/start.sh [STATE_DIR])"
#
# STATE_DIR (default: a new `mktemp -d`) receives slurm.conf, the munge key and socket,
# Slurm state/spool, logs (STATE_DIR/log) and the PIDs of the daemons started here
# (STATE_DIR/pids). Nothing outside STATE_DIR is written; a system Slurm/munge is untouched.
# On success stdout carries only shell lines to eval/source:
#   export SLURM_CONF=STATE_DIR/slurm.conf
#   export LOCAL_SLURM_STATE_DIR=STATE_DIR
# Progress and errors go to stderr. Exit codes: 0 up, 77 Slurm/munge not installed or not root, 1 failure
# (the daemons started so far are stopped again).
# Stop with: cluster/local-slurm/stop.sh STATE_DIR [--clean]
#
# Tunables (environment): LOCAL_SLURM_KILL_WAIT (10), LOCAL_SLURM_CRED_EXPIRE (10),
# LOCAL_SLURM_MIN_JOB_AGE (60), LOCAL_SLURM_START_TIMEOUT (30).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
log() { echo "local-slurm: $*" >&2; }
die() { log "error: $*"; exit 1; }

case "${1:-}" in
  -h|--help) sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | sed '$d; s/^# \{0,1\}//' >&2; exit 0 ;;
esac
[[ $# -le 1 ]] || die "usage: start.sh [STATE_DIR]"

# --- prerequisites (installing is .ci/install-deps --slurm's job) ---------------------------
for bin in slurmctld slurmd munged munge sinfo srun sbatch scontrol squeue scancel; do
  if ! command -v "$bin" >/dev/null 2>&1 && [[ ! -x /usr/sbin/$bin ]]; then
    echo "local Slurm unavailable: $bin not installed (run .ci/install-deps --slurm)" >&2
    exit 77
  fi
done
PATH=$PATH:/usr/sbin
# slurmd launches job steps as their owners and slurmstepd needs root for that; only root is tested.
if [[ $(id -u) -ne 0 ]]; then
  echo "local Slurm unavailable: it must be started as root (slurmd runs job steps as their owners)" >&2
  exit 77
fi

kill_wait=${LOCAL_SLURM_KILL_WAIT:-10}
cred_expire=${LOCAL_SLURM_CRED_EXPIRE:-10}
min_job_age=${LOCAL_SLURM_MIN_JOB_AGE:-60}
start_timeout=${LOCAL_SLURM_START_TIMEOUT:-30}
for v in kill_wait cred_expire min_job_age start_timeout; do
  [[ ${!v} =~ ^[0-9]+$ ]] || die "$v must be a whole number of seconds, got '${!v}'"
done
# Slurm rejects cred_expire < 5 ("AuthInfo=cred_expire=N invalid") and silently uses 120.
((cred_expire >= 5)) || die "LOCAL_SLURM_CRED_EXPIRE must be >= 5 (Slurm ignores smaller values)"

# --- state directory -------------------------------------------------------------------------
if [[ $# -eq 1 ]]; then
  state=$1
  [[ $state != *[[:space:]@\|]* ]] || die "STATE_DIR must not contain blanks, '@' or '|': $state"
  mkdir -p "$state"
else
  state=$(mktemp -d "${TMPDIR:-/tmp}/local-slurm.XXXXXX")
fi
state=$(cd "$state" && pwd -P)
[[ $state != *[[:space:]@\|]* ]] || die "STATE_DIR must not contain blanks, '@' or '|': $state"
if [[ -s $state/pids ]]; then
  while read -r name pid; do
    if [[ -d /proc/$pid ]] && ! grep -q '^State:.*Z' "/proc/$pid/status" 2>/dev/null &&
       [[ $(cat "/proc/$pid/comm" 2>/dev/null) == "$name" ]]; then
      die "$state already has running daemons (pid $pid); stop it first: $here/stop.sh $state"
    fi
  done <"$state/pids"
fi
mkdir -p "$state"/{ctld,spool,log,run,munge,tmp}
chmod 755 "$state/munge"   # munged warns unless the socket dir is world-searchable
: >"$state/pids"
: >"$state/plugstack.conf"   # empty: no SPANK plugins from /etc/slurm/plugstack.conf.d

conf=$state/slurm.conf
started=()
cleanup_on_failure() {
  local rc=$?
  if [[ $rc -ne 0 && ${#started[@]} -gt 0 ]]; then
    log "start failed; stopping the daemons started so far"
    "$here/stop.sh" "$state" >&2 || true
  fi
}
trap cleanup_on_failure EXIT

export SLURM_CONF="$conf"

# Start DAEMON ARGS... in the foreground of its own session, detached from our stdout,
# and record its PID. `setsid` execs directly (we are not a process-group leader), so $!
# is the daemon itself.
spawn() {
  local name=$1; shift
  setsid "$@" </dev/null >>"$state/log/$name.out" 2>&1 &
  local pid=$!
  echo "$name $pid" >>"$state/pids"
  started+=("$name")
  log "started $name (pid $pid)"
}

alive() { [[ -d /proc/$1 ]] && ! grep -q '^State:.*Z' "/proc/$1/status" 2>/dev/null; }
pid_of() { awk -v n="$1" '$1 == n { print $2 }' "$state/pids"; }

show_logs() {
  local f
  for f in "$state"/log/*; do
    [[ -s $f ]] || continue
    echo "----- tail $f" >&2
    tail -n 15 "$f" >&2
  done
}

# --- ports -----------------------------------------------------------------------------------
port_free() {
  if command -v ss >/dev/null 2>&1; then
    [[ -z $(ss -Htan "( sport = :$1 )" 2>/dev/null) ]]
  else
    if (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; then return 1; fi
  fi
}
ctld_port=
for _ in $(seq 1 100); do
  p=$((20000 + RANDOM % 20000))
  if port_free "$p" && port_free $((p + 1)); then ctld_port=$p; break; fi
done
[[ -n $ctld_port ]] || die "no free pair of TCP ports found in 20000-40000"
slurmd_port=$((ctld_port + 1))

# --- node hardware ---------------------------------------------------------------------------
hw=$(slurmd -C 2>/dev/null | head -n 1 || true)
cpus=$(sed -n 's/.*CPUs=\([0-9]*\).*/\1/p' <<<"$hw")
if [[ -n $cpus ]]; then
  # Keep the topology slurmd detects, with a 5 % memory margin so the node never registers
  # with less memory than configured (which would make it INVALID).
  mem=$(sed -n 's/.*RealMemory=\([0-9]*\).*/\1/p' <<<"$hw")
  node_hw=$(grep -o -E '(CPUs|Boards|SocketsPerBoard|CoresPerSocket|ThreadsPerCore)=[0-9]+' <<<"$hw" | tr '\n' ' ')
  node_hw="${node_hw}RealMemory=$((mem * 95 / 100))"
else
  cpus=$(nproc)
  mem=$(free -m | awk '/^Mem:/ { print $2 }')
  node_hw="CPUs=$cpus RealMemory=$((mem * 95 / 100))"
fi

user=$(id -un)
sed -e "s|@STATE_DIR@|$state|g" \
    -e "s|@SLURMCTLD_PORT@|$ctld_port|g" \
    -e "s|@SLURMD_PORT@|$slurmd_port|g" \
    -e "s|@SLURM_USER@|$user|g" \
    -e "s|@SLURMD_USER@|$user|g" \
    -e "s|@KILL_WAIT@|$kill_wait|g" \
    -e "s|@CRED_EXPIRE@|$cred_expire|g" \
    -e "s|@MIN_JOB_AGE@|$min_job_age|g" \
    -e "s|@NODE_HW@|$node_hw|g" \
    "$here/slurm.conf.in" >"$conf"
if grep -q '@[A-Z_]*@' "$conf"; then die "unfilled placeholder in $conf: $(grep -o '@[A-Z_]*@' "$conf" | head -n 1)"; fi
log "slurm.conf: $conf (slurmctld port $ctld_port, slurmd port $slurmd_port, $node_hw)"

# --- munged ----------------------------------------------------------------------------------
key=$state/munge/munge.key
sock=$state/munge/munge.socket
if [[ ! -s $key ]]; then
  if command -v mungekey >/dev/null 2>&1 || [[ -x /usr/sbin/mungekey ]]; then
    mungekey --create --keyfile="$key" >/dev/null 2>&1 || dd if=/dev/urandom of="$key" bs=1024 count=1 status=none
  else
    dd if=/dev/urandom of="$key" bs=1024 count=1 status=none
  fi
fi
chmod 400 "$key"
rm -f "$sock" "$sock.lock"
# --force: allowed to run as root and to start despite permission warnings (e.g. /tmp parents).
spawn munged munged --foreground --force --socket="$sock" --key-file="$key" \
  --log-file="$state/log/munged.log" --pid-file="$state/run/munged.pid" \
  --seed-file="$state/munge/munged.seed"
deadline=$((SECONDS + 10))
until munge -n -S "$sock" 2>/dev/null | unmunge -S "$sock" >/dev/null 2>&1; do
  alive "$(pid_of munged)" || { show_logs; die "munged exited during start-up"; }
  ((SECONDS < deadline)) || { show_logs; die "munged did not answer on $sock within 10 s"; }
  sleep 0.2
done

# --- slurmctld, slurmd -----------------------------------------------------------------------
spawn slurmctld slurmctld -D -f "$conf"
spawn slurmd slurmd -D -N localhost -f "$conf"

deadline=$((SECONDS + start_timeout))
state_now=
while :; do
  for d in slurmctld slurmd; do
    alive "$(pid_of "$d")" || { show_logs; die "$d exited during start-up (logs above, all in $state/log)"; }
  done
  state_now=$(sinfo -h -n localhost -o %T 2>/dev/null || true)
  [[ $state_now == idle ]] && break
  if ((SECONDS >= deadline)); then
    show_logs
    die "node not idle after ${start_timeout} s (sinfo state: '${state_now:-no answer}'; logs in $state/log)"
  fi
  sleep 0.5
done
log "node localhost idle; stop with: $here/stop.sh $state"

trap - EXIT
printf 'export SLURM_CONF=%q\n' "$conf"
printf 'export LOCAL_SLURM_STATE_DIR=%q\n' "$state"
