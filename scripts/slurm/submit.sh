#!/usr/bin/env bash
# Submits a villa dataset job to Slurm: a job array of shards and the merge as a job that runs once every
# task has succeeded. The array size, each task's time and memory come from measured rates
# (docs/BENCHMARKS.md "Cluster"), with a margin; override them with --tasks, --time, --mem, --cpus.
#   scripts/slurm/submit.sh synth  --out DIR --count N [--seed S] [--tasks T] [-- more villa synth flags]
#   scripts/slurm/submit.sh scenes --out DIR --layouts FILE [--seed S] [--tasks T] [-- more villa scenes flags]
# Shards go to DIR/shards/shard-IIII-of-NNNN, the merged dataset to DIR/merged, the logs to DIR/logs.
# Submitting the same job again after a kill or a timeout finishes it: every shard keeps what it has done.
# `villa dataset status DIR/shards` shows the progress. Prints the array's and the merge's job ids.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
usage() { sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
kind=${1:-}; shift || true
[[ $kind == synth || $kind == scenes ]] || usage
out="" count="" layouts="" seed=0 tasks="" time_limit="" mem="" cpus="" extra=()
while [[ $# -gt 0 ]]; do
  case $1 in
    --out) out=$2; shift 2 ;;
    --count) count=$2; shift 2 ;;
    --layouts) layouts=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --tasks) tasks=$2; shift 2 ;;
    --time) time_limit=$2; shift 2 ;;
    --mem) mem=$2; shift 2 ;;
    --cpus) cpus=$2; shift 2 ;;
    --) shift; extra=("$@"); break ;;
    *) echo "submit.sh: unknown option $1" >&2; usage ;;
  esac
done
[[ -n $out ]] || { echo "submit.sh: --out DIR is required" >&2; exit 2; }
villa=${VILLA:-$(command -v villa || true)}
[[ -z $villa && -x $here/../../build/cli/villa ]] && villa=$(cd "$here/../../build/cli" && pwd)/villa
[[ -n $villa && -x $villa ]] || { echo "submit.sh: no villa binary (set VILLA=/path/to/villa)" >&2; exit 2; }
mkdir -p "$out/logs"
out=$(cd "$out" && pwd)

# Measured on one core (docs/BENCHMARKS.md): synth ~1,000 layouts/s; scenes ~10 s a villa with procedural
# assets (the default 2:4:4 floor mix, physics and reachability on), ~25 s with the imported library, and
# at most ~0.13 GB (procedural) or ~0.4 GB (library) resident. Tasks are sized for ~30 minutes of work.
if [[ $kind == synth ]]; then
  [[ -n $count ]] || { echo "submit.sh: synth needs --count N" >&2; exit 2; }
  items=$count
  cpus=${cpus:-2}
  tasks=${tasks:-$(( (count + 999999) / 1000000 ))}
  per_task_s=$(( (count / tasks) / 1000 / cpus + 60 ))
  mem=${mem:-2G}
  args="--count $count --seed $seed ${extra[*]:-}"
else
  [[ -n $layouts && -f $layouts ]] || { echo "submit.sh: scenes needs --layouts FILE (a layouts.jsonl)" >&2; exit 2; }
  layouts=$(cd "$(dirname "$layouts")" && pwd)/$(basename "$layouts")
  items=$(grep -c . "$layouts")
  cpus=${cpus:-1}
  library=1
  [[ " ${extra[*]:-} " == *" --procedural "* ]] && library=0
  per_villa=$(( library ? 25 : 10 ))
  tasks=${tasks:-$(( (items * per_villa + 1799) / 1800 ))}
  (( tasks > items )) && tasks=$items
  per_task_s=$(( ((items + tasks - 1) / tasks) * per_villa * 2 / cpus + 300 ))
  mem=${mem:-$(( library ? 2 : 1 ))G}
  args="--seed $seed ${extra[*]:-}"
fi
(( tasks >= 1 )) || tasks=1
time_limit=${time_limit:-$(( (per_task_s + 59) / 60 ))}
echo "submit.sh: $kind of $items item(s) in $tasks task(s) of $cpus CPU(s), $mem and ${time_limit} min each" >&2

array=$(sbatch --parsable --array=0-$((tasks - 1)) --cpus-per-task="$cpus" --mem="$mem" --time="$time_limit" \
  --chdir="$out/logs" --export=ALL,VILLA="$villa",VILLA_OUT="$out",VILLA_LAYOUTS="$layouts",VILLA_ARGS="$args",VILLA_SHARDS="$tasks" \
  "$here/$kind.sbatch")
array=${array%%;*}
merge=$(sbatch --parsable --dependency=afterok:"$array" --kill-on-invalid-dep=yes --cpus-per-task=1 --mem=2G --time=60 \
  --chdir="$out/logs" --export=ALL,VILLA="$villa",VILLA_OUT="$out" "$here/merge.sbatch")
merge=${merge%%;*}
echo "array $array merge $merge"
