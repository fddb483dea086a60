#!/usr/bin/env bash
# End-to-end test of sharding on a real Slurm: starts a single-node cluster on this machine from
# Debian's packages (munged, slurmctld and slurmd as root, on the local host name, everything in
# a temporary folder: no file under /etc is touched), submits slurm/sweep_array.sbatch as an
# array of 4 shards, merges the shard journals with `agvbench merge`, and checks that
#   - the merged report equals an unsharded run (timing and environment aside) and is complete;
#   - a merge that misses a shard says so ("complete": false).
# The daemons are always stopped and the folder removed (KEEP_TMP=1 keeps it). Every wait is
# bounded; the whole test takes about a minute. Needs root.
#
# Usage: slurm/test_local_cluster.sh
# Env:   AGVBENCH (default build/agvbench; built by scripts/setup.sh when missing),
#        CONFIG (default slurm/test_config.json), KEEP_TMP=1
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$PWD
AGVBENCH=${AGVBENCH:-$repo/build/agvbench}
CONFIG=${CONFIG:-$repo/slurm/test_config.json}
shards=4

say() { echo "slurm-test: $*"; }
die() { echo "slurm-test: FAIL: $*" >&2; exit 1; }

[ "$(id -u)" -eq 0 ] || die "needs root (slurmctld, slurmd and munged run as root here)"
scripts/apt_need.sh slurm-wlm munge python3
[ -x "$AGVBENCH" ] || scripts/setup.sh
case $AGVBENCH in /*) ;; *) AGVBENCH=$repo/$AGVBENCH ;; esac
case $CONFIG in /*) ;; *) CONFIG=$repo/$CONFIG ;; esac

tmp=$(mktemp -d /tmp/agv-slurm.XXXXXX)
chmod 700 "$tmp"
mkdir -p "$tmp"/{munge,state,spool,log,shards,out}
pids=()  # daemons we started, in start order
sbatch_pid=

stop_daemons() {
  local i pid
  for ((i = ${#pids[@]} - 1; i >= 0; i--)); do  # slurmd, slurmctld, then munged
    pid=${pids[i]}
    kill -TERM "$pid" 2>/dev/null || continue
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.2; done
    kill -KILL "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
  done
  pids=()
}
cleanup() {
  local rc=$?
  trap - EXIT INT TERM
  if ((${#pids[@]} >= 3)); then  # cancel what still runs, so no job outlives its slurmd
    timeout 10 scancel --user=root >/dev/null 2>&1 || true
    for _ in $(seq 20); do
      [ -z "$(timeout 5 squeue -h -t running,completing -o %i 2>/dev/null)" ] && break
      sleep 0.5
    done
  fi
  [ -n "$sbatch_pid" ] && kill "$sbatch_pid" 2>/dev/null || true
  stop_daemons
  if ((rc != 0)); then
    for f in "$tmp"/log/*.log "$tmp"/out/*; do
      [ -s "$f" ] && { echo "---- ${f#"$tmp"/} (tail)"; tail -n 25 "$f"; }
    done >&2
  fi
  if [ "${KEEP_TMP:-0}" = 1 ]; then say "kept $tmp"; else rm -rf "$tmp"; fi
  exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# Waits up to SECONDS for COMMAND to succeed.
wait_for() {
  local seconds=$1 what=$2
  shift 2
  local end=$((SECONDS + seconds))
  until "$@" >/dev/null 2>&1; do
    ((SECONDS < end)) || die "timed out after ${seconds}s waiting for $what"
    sleep 0.5
  done
}

free_port() {
  /usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

host=$(hostname -s)
cpus=$(nproc)
ctld_port=$(free_port)
slurmd_port=$(free_port)
while [ "$slurmd_port" = "$ctld_port" ]; do slurmd_port=$(free_port); done

# munge: a fresh key and a private socket.
dd if=/dev/urandom of="$tmp/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$tmp/munge/munge.key"
socket=$tmp/munge/munge.socket
munged -F --force --key-file="$tmp/munge/munge.key" --socket="$socket" \
  --pid-file="$tmp/munge/munged.pid" --log-file="$tmp/log/munged.log" \
  --seed-file="$tmp/munge/munged.seed" >"$tmp/log/munged.out" 2>&1 &
pids+=($!)
wait_for 20 "munged" sh -c "munge --socket='$socket' -n | unmunge --socket='$socket'"
say "munged up"

export SLURM_CONF=$tmp/slurm.conf
cat >"$SLURM_CONF" <<EOF
ClusterName=agvtest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/log/slurmctld.log
SlurmdLogFile=$tmp/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
# Containers: no cgroups; processes tracked through /proc, no task binding.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SwitchType=switch/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MinJobAge=600
InactiveLimit=0
MailProg=/bin/true
KillWait=5
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=agv Nodes=$host Default=YES MaxTime=60 State=UP
EOF

slurmctld -D -i -f "$SLURM_CONF" >"$tmp/log/slurmctld.out" 2>&1 &
pids+=($!)
wait_for 30 "slurmctld" sh -c "scontrol ping | grep -q UP"
# slurmd (22.05) initialises its cgroup plugin even with the cgroup-free settings above.
mountpoint -q /sys/fs/cgroup ||
  die "slurmd needs a cgroup filesystem on /sys/fs/cgroup, and none is mounted here (a chroot without /sys mounted recursively?)"
slurmd -D -f "$SLURM_CONF" -N "$host" >"$tmp/log/slurmd.out" 2>&1 &
pids+=($!)
wait_for 60 "node $host idle" sh -c "sinfo -h -n '$host' -o %T | grep -qx idle"
say "cluster up: node $host, $cpus CPUs, slurmctld :$ctld_port, slurmd :$slurmd_port"

start=$SECONDS
rc=0
timeout 300 sbatch --wait --quiet --array=0-$((shards - 1)) --cpus-per-task=1 --time=10 \
  --chdir="$repo" --output="$tmp/out/slurm_%A_%a.out" \
  --export=ALL,CONFIG="$CONFIG",AGVBENCH="$AGVBENCH",SHARD_DIR="$tmp/shards" \
  slurm/sweep_array.sbatch &
sbatch_pid=$!
wait $sbatch_pid || rc=$?  # in the background, so that a signal is handled at once
((rc == 0)) || die "sbatch --wait: exit $rc (124: timed out after 300s)"
say "array of $shards shards done in $((SECONDS - start)) s"
for ((i = 0; i < shards; i++)); do
  [ -s "$tmp/shards/shard_$i.jsonl" ] || die "shard $i wrote no journal"
  [ -s "$tmp/shards/report_$i.json" ] || die "shard $i wrote no report"
done

timeout 300 "$AGVBENCH" run "$CONFIG" --threads "$cpus" --quiet --out "$tmp/unsharded.json"
journals=()
for ((i = 0; i < shards; i++)); do journals+=("$tmp/shards/shard_$i.jsonl"); done
timeout 120 "$AGVBENCH" merge "${journals[@]}" --config "$CONFIG" --out "$tmp/merged.json"
/usr/bin/python3 slurm/same_report.py "$tmp/unsharded.json" "$tmp/merged.json" ||
  die "the merged report differs from the unsharded run"
complete() { /usr/bin/python3 -c 'import json, sys; print(json.dumps(json.load(open(sys.argv[1])).get("complete")))' "$1"; }
[ "$(complete "$tmp/merged.json")" = true ] || die "the merged report is not marked complete"

# Without shard 2: the report must say it is incomplete, not average what is there.
timeout 120 "$AGVBENCH" merge "${journals[0]}" "${journals[1]}" "${journals[3]}" \
  --config "$CONFIG" --out "$tmp/partial.json" || true
[ -s "$tmp/partial.json" ] || die "merge without shard 2 wrote no report"
[ "$(complete "$tmp/partial.json")" = false ] ||
  die "a merge without shard 2 is not marked incomplete"
say "missing shard reported: \"complete\": false"
say "PASS: $shards Slurm array shards merged = the unsharded report"
