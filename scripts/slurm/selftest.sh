#!/usr/bin/env bash
# The cluster path end to end on a single-node Slurm cluster started here (local-cluster.sh, its own
# folder and ports): `villa synth` as an 8-task job array with the merge as a dependent job, byte-identical
# to one machine's run; `villa scenes` of 8 villas as a 4-task array, cancelled midway (scancel) and
# submitted again, its merge equal to one machine's run file for file; `villa dataset verify` on both.
#   scripts/slurm/selftest.sh VILLA_BINARY [WORK_DIR]
# Exit 0 when all holds, 1 with the reason, 77 when this machine cannot run a cluster (not root, no Slurm,
# or the daemons do not start).
set -euo pipefail
villa=$(readlink -f "$1")
# WORK_DIR: where the cluster, the runs and the logs go (kept, to read after a failure); without it a
# temporary folder, removed when everything held.
if [[ -n ${2:-} ]]; then
  work=$2
  own_work=no
else
  work=$(mktemp -d /tmp/villa-slurm-selftest.XXXXXX)
  own_work=yes
fi
here=$(cd "$(dirname "$0")" && pwd)
[[ $(id -u) == 0 ]] || { echo "selftest: needs root to run slurmd" >&2; exit 77; }
command -v sbatch >/dev/null && command -v munged >/dev/null || { echo "selftest: slurm-wlm or munge not installed" >&2; exit 77; }
fail() { echo "selftest: $*" >&2; exit 1; }
export VILLA_SLURMCTLD_PORT=${VILLA_SLURMCTLD_PORT:-6917} VILLA_SLURMD_PORT=${VILLA_SLURMD_PORT:-6918}
cluster=$work/cluster
trap '"$here/local-cluster.sh" stop "$cluster" >/dev/null 2>&1 || true' EXIT
# A machine where slurmd cannot start (a container without the privileges it needs) cannot run the test:
# said, with the daemons' last words, and not counted as a failure of villa.
if ! "$here/local-cluster.sh" start "$cluster" >"$work/cluster-start.log" 2>&1; then
  echo "selftest: the local cluster did not start on this machine:" >&2
  tail -n 20 "$work/cluster-start.log" >&2
  exit 77
fi
export SLURM_CONF=$cluster/slurm.conf VILLA=$villa

# Waits for a job (and its array tasks) to leave the queue.
wait_job() {
  for _ in $(seq 1200); do
    [[ -z $(squeue -h -j "$1" 2>/dev/null) ]] && return 0
    sleep 0.25
  done
  fail "job $1 still queued after 300 s"
}

# Synth: 2,000 layouts in 8 tasks.
"$villa" synth --count 2000 --seed 9 --out "$work/synth-one" >/dev/null
read -r _ array _ merge < <("$here/submit.sh" synth --out "$work/synth" --count 2000 --seed 9 --tasks 8 --cpus 1 2>/dev/null)
wait_job "$array"; wait_job "$merge"
cmp -s "$work/synth/merged/layouts.jsonl" "$work/synth-one/layouts.jsonl" || fail "merged synth layouts.jsonl differs from one machine's"
cmp -s "$work/synth/merged/manifest.json" "$work/synth-one/manifest.json" || fail "merged synth manifest.json differs from one machine's"
"$villa" dataset verify "$work/synth/merged" >/dev/null || fail "synth verify"
echo "selftest: synth 2000 layouts in 8 tasks, merged byte-identical to one machine's run"

# Scenes: 8 single-storey villas in 4 tasks, cancelled as soon as a shard is part done, then resubmitted.
"$villa" synth --count 8 --seed 5 --floors 1:0:0 --out "$work/layouts" >/dev/null
flags=(--procedural --critic none --no-reach)
"$villa" scenes "$work/layouts/layouts.jsonl" --out "$work/scenes-one" --seed 3 "${flags[@]}" -q || fail "one-machine scenes"
read -r _ array _ merge < <("$here/submit.sh" scenes --out "$work/scenes" --layouts "$work/layouts/layouts.jsonl" --seed 3 --tasks 4 --cpus 1 -- "${flags[@]}" 2>/dev/null)
cancelled=no
for _ in $(seq 1200); do
  if grep -qs '"complete": false' "$work"/scenes/shards/*/progress.json && grep -qs '"done": 1,' "$work"/scenes/shards/*/progress.json; then
    scancel "$array"; cancelled=yes; break
  fi
  [[ -z $(squeue -h -j "$array" 2>/dev/null) ]] && break
  sleep 0.05
done
wait_job "$array"; wait_job "$merge"
[[ ! -e $work/scenes/merged ]] || [[ $cancelled == no ]] || fail "the merge ran after its array was cancelled"
echo "selftest: scenes array cancelled midway: $cancelled"
read -r _ array _ merge < <("$here/submit.sh" scenes --out "$work/scenes" --layouts "$work/layouts/layouts.jsonl" --seed 3 --tasks 4 --cpus 1 -- "${flags[@]}" 2>/dev/null)
wait_job "$array"; wait_job "$merge"
[[ -f $work/scenes/merged/scenes.jsonl ]] || fail "no merged scenes (logs in $work/scenes/logs)"
"$villa" dataset verify "$work/scenes/merged" >/dev/null || fail "scenes verify"
n=0
while IFS= read -r f; do
  cmp -s "$work/scenes-one/$f" "$work/scenes/merged/$f" || fail "$f differs from one machine's run"
  n=$((n + 1))
done < <(cd "$work/scenes-one" && find scenes -type f ! -name entry.json | sort)
[[ $n -eq 40 ]] || fail "expected 40 villa files, compared $n"
[[ $(find "$work/scenes/shards" -name '.tmp-*' | wc -l) -eq 0 ]] || fail "a temporary villa folder was kept"
echo "selftest: scenes 8 villas in 4 tasks (resubmitted), merged equal to one machine's run file for file ($n files)"
"$here/local-cluster.sh" stop "$cluster" >/dev/null 2>&1 || true
if [[ $own_work == yes ]]; then rm -rf "$work"; fi
exit 0
