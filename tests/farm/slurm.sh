#!/usr/bin/env bash
# The Slurm recipe (examples/farm/slurm/) against a real Slurm: a one-node
# cluster on this machine, from Debian's packages.
#
#   sudo bash tests/farm/slurm.sh        (root, Debian or Ubuntu, no systemd needed)
#
# It installs slurm-wlm and munge with apt-get, writes a slurm.conf for this
# host alone, starts munged, slurmctld and slurmd in the foreground of
# background jobs (and stops them at the end), takes target/release/rts (or
# builds it; RTS=/path/to/rts to use another), then:
#   1. submits a 3-task array rendering a 12-frame animation with --shard I/3,
#      and a dependent (afterok) job that checks the manifests and assembles a
#      GIF and an APNG; asserts the frames are byte-identical to one local run;
#   2. submits the array again into a fresh folder, cancels task 1 (scancel)
#      while it renders, then submits the same array again and asserts it
#      rendered only the missing frames (rts's own "rendered R, skipped S"
#      lines; the frames kept have their old mtimes) and that the frames are
#      byte-identical to the local run;
#   3. splits a still over a 3-task array (--shard I/3: row bands) with a
#      dependent `rts merge`, and asserts the merged image is byte-identical to
#      one local render.
# Prints what it does with timings, and "slurm: N passed, 0 failed" at the
# end. Leaves its work folder (printed) for inspection. It overwrites
# /etc/slurm/slurm.conf and cgroup.conf: run it on a throwaway machine or
# container (CI), not on a real cluster.
set -euo pipefail
cd "$(dirname "$0")/../.."
repo=$PWD
t0=$(date +%s)
say() { echo "[$(( $(date +%s) - t0 ))s] $*"; }
passed=0
check() { # check DESCRIPTION COMMAND...
  local what=$1; shift
  if "$@"; then passed=$((passed + 1)); say "ok: $what"; else say "FAILED: $what"; echo "slurm: $passed passed, 1 failed"; exit 1; fi
}

[ "$(id -u)" = 0 ] || { echo "slurm.sh: run as root (it installs and starts Slurm)" >&2; exit 2; }
command -v apt-get >/dev/null || { echo "slurm.sh: needs apt-get (Debian or Ubuntu)" >&2; exit 2; }

# --- Slurm and munge from Debian -------------------------------------------
if ! command -v slurmctld >/dev/null || ! command -v slurmd >/dev/null || ! command -v munged >/dev/null; then
  say "installing slurm-wlm and munge from Debian"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends slurm-wlm munge >/dev/null
fi
say "$(slurmctld -V), munge $(munged -V 2>&1 | head -1)"

host=$(hostname -s)
work=$(mktemp -d /tmp/rts-slurm.XXXXXX)
chmod 755 "$work"
etc=/etc/slurm
mkdir -p "$etc" /var/spool/slurmctld /var/spool/slurmd /var/log/slurm /run/munge /var/lib/munge /var/log/munge
cpus=$(nproc)
cat > "$etc/slurm.conf" <<EOF
# One-node cluster for tests/farm/slurm.sh (written by it).
ClusterName=rtsfarm
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=6817
SlurmdPort=6818
AuthType=auth/munge
StateSaveLocation=/var/spool/slurmctld
SlurmdSpoolDir=/var/spool/slurmd
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MinJobAge=600
SlurmctldTimeout=30
SlurmdTimeout=30
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=farm Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
# slurmd (22.05) loads a cgroup plugin even when nothing is confined
# (proctrack/linuxproc, task/none): the one for what is mounted, without systemd.
if [ "$(stat -fc %T /sys/fs/cgroup 2>/dev/null)" = cgroup2fs ]; then
  printf 'CgroupPlugin=cgroup/v2\nIgnoreSystemd=yes\n' > "$etc/cgroup.conf"
else
  printf 'CgroupPlugin=cgroup/v1\nCgroupAutomount=yes\n' > "$etc/cgroup.conf"
fi

# --- daemons -----------------------------------------------------------------
pids=()
stop() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  for p in "${pids[@]}"; do wait "$p" 2>/dev/null || true; done
}
trap stop EXIT
if [ ! -s /etc/munge/munge.key ]; then
  mkdir -p /etc/munge
  dd if=/dev/urandom of=/etc/munge/munge.key bs=1024 count=1 status=none
fi
chown -R munge:munge /etc/munge /run/munge /var/lib/munge /var/log/munge
chmod 700 /etc/munge; chmod 400 /etc/munge/munge.key
if ! munge -n </dev/null >/dev/null 2>&1; then
  runuser -u munge -- munged --foreground --force > "$work/munged.log" 2>&1 &
  pids+=($!)
  for _ in $(seq 50); do munge -n </dev/null >/dev/null 2>&1 && break; sleep 0.1; done
fi
check "munge works" sh -c 'munge -n </dev/null | unmunge >/dev/null'
slurmctld -D -c -i > "$work/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -N "$host" > "$work/slurmd.out" 2>&1 &
pids+=($!)
ready=no
for _ in $(seq 300); do
  if sinfo -h -N -o '%T' 2>/dev/null | grep -Eq '^(idle|mixed|allocated)'; then ready=yes; break; fi
  sleep 0.2
done
if [ $ready != yes ]; then
  scontrol update nodename="$host" state=resume 2>/dev/null || true
  sleep 1
  sinfo -h -N -o '%T' 2>/dev/null | grep -Eq '^(idle|mixed)' && ready=yes
fi
[ $ready = yes ] || tail -n 20 "$work"/slurm*.log >&2
check "slurm node $host is up ($(sinfo -h -N -o '%N %T %c' 2>/dev/null))" test $ready = yes

# --- rts -----------------------------------------------------------------------
rts=${RTS:-$repo/target/release/rts}
if [ ! -x "$rts" ]; then
  say "building rts (cargo build --release)"
  CARGO_BUILD_JOBS=${CARGO_BUILD_JOBS:-2} cargo build --release -q
fi
export RTS=$rts
recipe=$repo/examples/farm/slurm
cp "$repo/examples/anim_easing.rts" "$work/scene.rts"
cp "$repo/examples/area_light.rts" "$work/still.rts"
cd "$work"
mkdir -p logs
# 12 frames of 320x240 with 16 samples a pixel: about a second each on one core.
opts=(-W 320 -H 240 --samples 16 --frames 1..12)
still_opts=(-W 320 -H 240 --antialias 0.1)
N=3

# Waits for jobs to leave the queue; fails when one did not complete.
wait_jobs() {
  for _ in $(seq 900); do
    [ -z "$(squeue -h -j "$(IFS=,; echo "$*")" 2>/dev/null)" ] && break
    sleep 0.2
  done
  local bad=0 j
  for j in "$@"; do
    local info state
    info=$(scontrol show job -o "$j" 2>/dev/null || true)
    state=$(echo "$info" | grep -o 'JobState=[A-Z_]*' | head -1)
    echo "  job $j: $(echo "$info" | grep -o 'JobName=[^ ]*' | head -1) $state $(echo "$info" | grep -o 'RunTime=[^ ]*' | head -1)"
    [ "$state" = JobState=COMPLETED ] || bad=1
  done
  return $bad
}

same_frames() { # same_frames DIR: every frame of DIR equals ref/
  local f k=0
  for f in ref/f_*.png; do
    cmp -s "$f" "$1/$(basename "$f")" || { echo "  $1/$(basename "$f") differs from $f" >&2; return 1; }
    k=$((k + 1))
  done
  echo "  $k frames in $1 are byte-identical to ref/"
  [ "$k" -eq 12 ]
}

# --- 1. one local run, then the array and the dependent assembly ---------------------
say "local reference run: rts render scene.rts -o ref/f_####.png ${opts[*]}"
s=$(date +%s%3N)
"$rts" render scene.rts -o ref/f_####.png "${opts[@]}" 2>&1 | tail -1
say "local run took $(( $(date +%s%3N) - s )) ms"

s=$(date +%s%3N)
array=$(sbatch --parsable --array=1-$N --output=logs/render_%A_%a.log \
  "$recipe/render.sbatch" scene.rts farm/f_####.png "${opts[@]}")
assemble=$(sbatch --parsable --dependency=afterok:$array --kill-on-invalid-dep=yes --output=logs/assemble_%j.log \
  "$recipe/assemble.sbatch" sequence scene.rts farm/f_####.png "${opts[@]}" --gif farm/anim.gif --apng farm/anim.png)
say "submitted array $array (tasks 1-$N) and assembly $assemble (afterok:$array)"
check "array and assembly completed" wait_jobs "${array}_1" "${array}_2" "${array}_3" "$assemble"
say "farm run took $(( $(date +%s%3N) - s )) ms"
for i in $(seq $N); do grep -h "sequence" "logs/render_${array}_$i.log" | sed 's/^/  /'; done
sed 's/^/  /' "logs/assemble_$assemble.log"
check "frames rendered by the array are byte-identical to the local run" same_frames farm
check "the assembly wrote a GIF and an APNG" test -s farm/anim.gif -a -s farm/anim.png

# --- 2. cancel a task mid-way, submit again --------------------------------------------
array=$(sbatch --parsable --array=1-$N --output=logs/kill_%A_%a.log \
  "$recipe/render.sbatch" scene.rts again/f_####.png "${opts[@]}")
say "submitted array $array into again/; cancelling task 1 once it has finished a frame"
man=again/f_####.png.shard-1-of-$N.manifest.json
for _ in $(seq 600); do
  [ -f "$man" ] && [ "$(grep -c '"file"' "$man")" -ge 1 ] && break
  sleep 0.1
done
scancel "${array}_1"
say "scancel ${array}_1 (its manifest lists $(grep -c '"file"' "$man") of 4 frames)"
wait_jobs "${array}_1" "${array}_2" "${array}_3" || true
sed 's/^/  /' "logs/kill_${array}_1.log"
have=$(ls again/f_*.png | wc -l)
missing=$((12 - have))
say "after the cancel: $have of 12 frames, $missing missing"
check "the cancelled task left frames to render" test "$missing" -gt 0
ls -l --time-style=+%T.%N again/f_*.png | awk '{print $6, $7}' > before.txt
sleep 1
array=$(sbatch --parsable --array=1-$N --output=logs/resubmit_%A_%a.log \
  "$recipe/render.sbatch" scene.rts again/f_####.png "${opts[@]}")
say "submitted the same array again: $array"
check "the re-submitted array completed" wait_jobs "${array}_1" "${array}_2" "${array}_3"
rendered=0
for i in $(seq $N); do
  line=$(grep -h "^sequence" "logs/resubmit_${array}_$i.log")
  echo "  task $i: $line"
  r=$(echo "$line" | sed -n 's/.*rendered \([0-9]*\), skipped.*/\1/p')
  rendered=$((rendered + r))
done
say "the re-submission rendered $rendered frames; $missing were missing"
check "the re-submission rendered only the missing frames" test "$rendered" -eq "$missing"
ls -l --time-style=+%T.%N again/f_*.png | awk '{print $6, $7}' > after.txt
kept=$(grep -Fxf before.txt after.txt | wc -l)
check "the $have frames kept were not written again (same mtimes)" test "$kept" -eq "$have"
check "frames after the re-submission are byte-identical to the local run" same_frames again

# --- 3. a still split into row bands, merged by a dependent job ---------------------------
say "local reference still: rts render still.rts -o ref/still.png ${still_opts[*]}"
"$rts" render still.rts -o ref/still.png "${still_opts[@]}" -q
array=$(sbatch --parsable --array=1-$N --output=logs/still_%A_%a.log \
  "$recipe/render.sbatch" still.rts bands/still.png "${still_opts[@]}")
merge=$(sbatch --parsable --dependency=afterok:$array --kill-on-invalid-dep=yes --output=logs/merge_%j.log \
  "$recipe/assemble.sbatch" still bands/still.png)
say "submitted still array $array and merge $merge (afterok:$array)"
check "still array and merge completed" wait_jobs "${array}_1" "${array}_2" "${array}_3" "$merge"
for i in $(seq $N); do grep -h "^part" "logs/still_${array}_$i.log" | sed 's/^/  /'; done
sed 's/^/  /' "logs/merge_$merge.log"
check "the merged still is byte-identical to one local render" cmp bands/still.png ref/still.png

say "work folder: $work"
echo "slurm: $passed passed, 0 failed"
