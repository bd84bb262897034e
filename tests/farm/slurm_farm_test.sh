#!/usr/bin/env bash
# `pyro farm` on a real cluster: a single-node Slurm (munged, slurmctld, slurmd) started by this
# script with every state, spool, pid, socket and log path in one temporary folder, then
#  1. a 60-frame render of content/scenes/explosion.json at 160x90 (small, to keep CI short)
#     submitted in chunks of 10, collected, and every frame compared byte for byte (cmp) with one
#     `pyro render` of the same range; the two wall times are printed;
#  2. the same job with one task's pyro killed (SIGKILL) mid-chunk: the collect job must report
#     that chunk missing and fail, `pyro farm resubmit` renders it again (resuming what the
#     killed task finished) and the frames must again equal the single render's;
#  3. one chunk's frames deleted from the collected folder: `pyro farm collect` names the range
#     and exits non-zero.
# Usage: slurm_farm_test.sh PYRO   (ctest: the slurm_farm test, label "slurm").
# Needs root (the daemons run as root, as in CI) and Debian's slurm-wlm and munge. Without root
# it exits 77 (ctest's skip), or fails when $CI is set; as root without the packages it fails.
# PYRO_FARM_TEST_CPUS sets the node's CPU count (default: all), so that a timing run can put the
# tasks one after another.
set -euo pipefail

fail() {
  echo "slurm_farm_test: FAIL: $*" >&2
  exit 1
}
[ $# -eq 1 ] || fail "usage: slurm_farm_test.sh PYRO"
if [ "$(id -u)" -ne 0 ]; then
  # CI runs as root and must run this test: there, not being root is a failure.
  [ -z "${CI:-}" ] || fail "CI is set but this is not root: starting munged, slurmctld and slurmd needs root"
  echo "slurm_farm_test: SKIP: starting munged, slurmctld and slurmd needs root (CI runs as root)"
  exit 77
fi
for tool in /usr/sbin/munged /usr/sbin/slurmctld /usr/sbin/slurmd munge unmunge sbatch squeue sinfo; do
  command -v "$tool" >/dev/null ||
    fail "$tool is missing: install slurm-wlm and munge (tools/install-deps.sh)"
done

pyro=$(readlink -f "$1")
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
scene=$source_dir/content/scenes/explosion.json
size=(--width 160 --height 90)
tmp=$(mktemp -d /tmp/pyro-slurm-test.XXXXXX)
host=$(hostname -s)
cpus=${PYRO_FARM_TEST_CPUS:-$(nproc)}

# Only the daemons this script started, by their pid files; the folder goes when all went well.
stop_daemons() {
  local status=$?
  # Jobs first: a job step (slurmstepd) still running when slurmd goes would wait for it for
  # minutes. Once the queue is empty every step has reported its end and exits.
  if [ -s "$tmp/slurmctld.pid" ]; then
    scancel --user=root 2>/dev/null || true
    for _ in $(seq 100); do
      [ -z "$(squeue -h -o %i 2>/dev/null)" ] && break
      sleep 0.2
    done
    sleep 0.5
  fi
  for f in slurmd.pid slurmctld.pid munged.pid; do
    [ -s "$tmp/$f" ] && kill "$(cat "$tmp/$f" 2>/dev/null)" 2>/dev/null || true
  done
  for f in slurmd.pid slurmctld.pid munged.pid; do
    for _ in $(seq 50); do
      [ -s "$tmp/$f" ] && kill -0 "$(cat "$tmp/$f" 2>/dev/null)" 2>/dev/null || break
      sleep 0.1
    done
  done
  if [ $status -eq 0 ]; then rm -rf "$tmp"; else echo "slurm_farm_test: logs kept in $tmp" >&2; fi
}
trap stop_daemons EXIT

start_munge() {
  head -c 1024 /dev/urandom >"$tmp/munge.key"
  chmod 600 "$tmp/munge.key"
  # --force: munged would refuse the temporary folder's parent (/tmp is writable by all).
  /usr/sbin/munged --force --socket="$tmp/munge.socket" --key-file="$tmp/munge.key" \
    --pid-file="$tmp/munged.pid" --log-file="$tmp/munged.log" --seed-file="$tmp/munged.seed" ||
    fail "munged did not start: $(cat "$tmp/munged.log" 2>/dev/null)"
  munge -n --socket="$tmp/munge.socket" | unmunge --socket="$tmp/munge.socket" >/dev/null ||
    fail "munge does not answer on $tmp/munge.socket"
}

write_slurm_conf() {
  mkdir -p "$tmp/state" "$tmp/spool"
  # sched_interval=1: the scheduler's periodic pass every second instead of every minute, so a
  # dependent job starts soon after the array ends (a 4-task array of 1 s tasks: 9 s -> 6 s).
  cat >"$tmp/slurm.conf" <<CONF
ClusterName=pyrotest
SlurmctldHost=$host
SlurmctldPort=16817
SlurmdPort=16818
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$tmp/munge.socket
CredType=cred/munge
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/builtin
SchedulerParameters=sched_interval=1
ReturnToService=2
MailProg=/bin/true
NodeName=$host CPUs=$cpus State=UNKNOWN
PartitionName=farm Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
  export SLURM_CONF=$tmp/slurm.conf
}

start_slurm() {
  /usr/sbin/slurmctld -i || fail "slurmctld did not start: $(tail -5 "$tmp/slurmctld.log")"
  /usr/sbin/slurmd || fail "slurmd did not start: $(tail -5 "$tmp/slurmd.log")"
  for _ in $(seq 100); do
    [ "$(sinfo -h -o %t 2>/dev/null)" = idle ] && return
    sleep 0.2
  done
  fail "the node is not idle after 20 s: $(sinfo 2>&1); $(tail -5 "$tmp/slurmd.log")"
}

# Waits until the queue is empty (every job ended).
wait_for_jobs() {
  for _ in $(seq 1200); do
    [ -z "$(squeue -h -o %i)" ] && return
    sleep 0.25
  done
  squeue >&2
  fail "jobs still queued after 300 s"
}

now() { date +%s.%N; }
seconds_since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }'; }

# Every frame of the single render is in FOLDER with the same bytes, and nothing else is.
same_frames() {
  local folder=$1 n=0
  for f in "$tmp/single"/frame_*.png; do
    cmp -s "$f" "$folder/$(basename "$f")" || fail "$folder/$(basename "$f") differs from the single render's"
    n=$((n + 1))
  done
  [ $n -eq 60 ] || fail "the single render made $n frames, not 60"
  [ "$(find "$folder" -maxdepth 1 -name 'frame_*' | wc -l)" -eq 60 ] || fail "$folder holds other frames"
  (cd "$folder" && sha256sum --quiet -c SHA256SUMS) || fail "$folder/SHA256SUMS does not check"
}

job_of() { sed -n "s/.*$1 \([0-9][0-9]*\).*/\1/p" "$2"; }

start_munge
write_slurm_conf
start_slurm
echo "slurm_farm_test: single-node Slurm up ($host, $cpus CPU(s)) in $tmp"

t0=$(now)
"$pyro" render "$scene" --out "$tmp/single" --frames 0:59 "${size[@]}" >/dev/null
single_s=$(seconds_since "$t0")

# 1. A whole job.
t0=$(now)
"$pyro" farm submit "$scene" --out "$tmp/farm" --frames 0:59 --chunk 10 "${size[@]}" | tee "$tmp/submit.txt"
wait_for_jobs
farm_s=$(seconds_since "$t0")
collect_job=$(job_of "collect job" "$tmp/submit.txt")
grep -q "collected frames 0:59" "$tmp/farm/.farm/logs/collect-$collect_job.log" ||
  fail "the collect job did not collect: $(cat "$tmp/farm/.farm/logs/collect-$collect_job.log")"
same_frames "$tmp/farm"
echo "slurm_farm_test: 60 frames, 6 tasks, byte-identical to one render"
# Each task's pyro says how long its render took ("... in 0.52 s"): the rest is Slurm's and the
# processes' start.
tasks_s=$(sed -n 's/^rendered .* in \([0-9.]*\) s$/\1/p' "$tmp/farm/.farm/logs"/render-*.log |
  awk '{ s += $1 } END { printf "%.1f", s }')
echo "slurm_farm_test: timing: single pyro render ${single_s} s; farm (submit to collected, $cpus CPU(s)) ${farm_s} s; overhead per task $(awk -v f="$farm_s" -v s="$single_s" 'BEGIN { printf "%.2f", (f - s) / 6 }') s; the 6 tasks' own render times add up to ${tasks_s} s"

# 2. A task killed mid-chunk, then resubmitted.
"$pyro" farm submit "$scene" --out "$tmp/fault" --frames 0:59 --chunk 10 "${size[@]}" >"$tmp/submit2.txt"
chunk=$tmp/fault/.farm/chunks/10-19
# A chunk at 160x90 draws in well under a second, too fast to catch by looking: the task's pyro
# is stopped as soon as its staging folder (named after its process id) appears, then let run
# 20 ms at a time until it has finished a frame, and killed there, mid-chunk.
for _ in $(seq 3000); do
  compgen -G "$chunk/.partial-*" >/dev/null && break
  sleep 0.01
done
staging=$(compgen -G "$chunk/.partial-*" | head -1 || true)
[ -n "$staging" ] || fail "task 1 never started rendering into $chunk"
task_pid=${staging##*.partial-}
kill -STOP "$task_pid"
for _ in $(seq 3000); do
  compgen -G "$staging/frame_*.png" >/dev/null && break
  kill -CONT "$task_pid"
  sleep 0.02
  kill -STOP "$task_pid"
done
compgen -G "$staging/frame_*.png" >/dev/null || fail "task 1 finished no frame in $staging"
kill -KILL "$task_pid"
! compgen -G "$chunk/frame_*" >/dev/null || fail "the killed task left frames in $chunk itself"
wait_for_jobs
first_collect=$(job_of "collect job" "$tmp/submit2.txt")
grep -q "missing frames 10:19" "$tmp/fault/.farm/logs/collect-$first_collect.log" ||
  fail "the collect job did not report the killed chunk: $(cat "$tmp/fault/.farm/logs/collect-$first_collect.log")"
"$pyro" farm resubmit "$tmp/fault" | tee "$tmp/resubmit.txt"
grep -q "1 task(s): frames 10:19)" "$tmp/resubmit.txt" || fail "resubmit sent more than the killed chunk"
wait_for_jobs
grep -q "resuming: [1-9]" "$tmp/fault/.farm/logs/render-$(job_of "render job array" "$tmp/resubmit.txt")_0.log" ||
  fail "the resubmitted task did not keep the frames the killed one finished"
"$pyro" farm collect "$tmp/fault" >/dev/null
same_frames "$tmp/fault"
echo "slurm_farm_test: killed task resubmitted; frames byte-identical to one render"

# 3. A chunk's frames deleted.
rm "$tmp/farm"/frame_002[0-9].png
if "$pyro" farm collect "$tmp/farm" 2>"$tmp/collect_err.txt"; then fail "collect succeeded with frames 20:29 deleted"; fi
grep -q "missing frames 20:29" "$tmp/collect_err.txt" || fail "collect did not name 20:29: $(cat "$tmp/collect_err.txt")"
echo "slurm_farm_test: a deleted chunk is reported as missing frames 20:29"
echo "slurm_farm_test: PASS"
