#!/usr/bin/env bash
# Every deterministic output of the villa command, made by two binaries and compared byte for byte:
# synth with a seed (layouts, stats, previews), validate --json (examples, fixtures, the synth output),
# render SVG and PNG, build .glb/.obj and the preview PNG (examples and some synth layouts; again with the
# door leaves hung shut),
# finetune export of an annotated fixture, plan, eval and generate on sample requests, and (with --dataset)
# the reference dataset recipe of scripts/make-dataset.sh.
# Usage: scripts/compare-outputs.sh [--dataset] OLD_VILLA NEW_VILLA [WORKDIR]
# Prints one line per file that differs (or is missing on one side) and exits 1 when any does.
set -euo pipefail
DATASET=0
if [[ ${1:-} == --dataset ]]; then DATASET=1; shift; fi
if [[ $# -lt 2 || $# -gt 3 ]]; then
  echo "usage: $0 [--dataset] OLD_VILLA NEW_VILLA [WORKDIR]" >&2
  exit 2
fi
OLD=$(realpath "$1")
NEW=$(realpath "$2")
ROOT=$(cd "$(dirname "$0")/.." && pwd)
WORK=${3:-$(mktemp -d "${TMPDIR:-/tmp}/villa-compare.XXXXXX")}
mkdir -p "$WORK"

# Runs every command with binary $1 into folder $2; exit codes are recorded, not fatal.
produce() {
  local villa=$1 out=$2
  rm -rf "$out"
  mkdir -p "$out"
  run() {
    local name=$1 rc=0
    shift
    "$@" > "$out/$name.stdout" 2> "$out/$name.stderr" || rc=$?
    echo $rc > "$out/$name.rc"
  }
  run synth "$villa" synth --count 36 --seed 7 --floors 1:1:1 --threads 2 --previews 12 --out "$out/synth"
  rm -f "$out/synth/manifest.json.tmp"
  local samples=()
  for i in 1 5 9 14 22 30; do
    sed -n "${i}p" "$out/synth/layouts.jsonl" | python3 -c 'import json,sys; print(json.dumps(json.load(sys.stdin)["layout"]))' \
      > "$out/synth-$i.json"
    samples+=("$out/synth-$i.json")
  done
  local layouts=("$ROOT"/examples/*.json "$ROOT"/tests/fixtures/layouts/*.json)
  for f in "${layouts[@]}"; do
    local b; b=$(basename "$f" .json)
    run "validate-$b" "$villa" validate --json "$f"
    run "render-svg-$b" "$villa" render "$f" -o "$out/$b.svg"
    run "render-png-$b" "$villa" render "$f" -o "$out/$b.png"
  done
  run validate-synth "$villa" validate --json "$out/synth/layouts.jsonl"
  for f in "$ROOT"/examples/*.json "${samples[@]}"; do
    local b; b=$(basename "$f" .json)
    run "build-$b" "$villa" build "$f" -o "$out/$b.glb" --preview "$out/$b.preview.png"
  done
  # With the leaves hung shut, door swings aside, every other part of the 3D output shows.
  for f in "$ROOT"/examples/*.json "${samples[@]}"; do
    local b; b=$(basename "$f" .json)
    run "build-closed-$b" "$villa" build "$f" -o "$out/$b.closed.glb" --preview "$out/$b.closed.png" --closed-doors
  done
  run build-obj "$villa" build "$ROOT/examples/two-floor-house.json" -o "$out/two-floor-house.obj"
  mkdir -p "$out/plan"
  run finetune "$villa" finetune export "$ROOT/tests/fixtures/finetune/annotated.jsonl" --out "$out/finetune" --seed 3
  run generate "$villa" generate "I want a two-story L-shaped villa with a living room, a kitchen, a bathroom, two bedrooms and a balcony." \
    --seed 5 --out "$out/generate"
  run plan "$villa" plan "A one-story U-shaped bungalow with a living room, a kitchen, a dining room and two bedrooms." \
    --seed 2 -o "$out/plan/layout.json"
  run eval "$villa" eval "$ROOT/tests/fixtures/prompts/varied.jsonl" --json --jobs 2 --limit 8
  run eval-text "$villa" eval "$ROOT/tests/fixtures/prompts/varied.jsonl" --jobs 2 --limit 8
  if [[ $DATASET == 1 ]]; then
    run dataset-synth "$villa" synth --count 1000 --floors 2:4:4 --seed 2026 --out "$out/dataset/synth"
    run dataset-auto "$villa" annotate "$out/dataset/synth" --auto
    run dataset-annotated "$villa" annotate "$out/dataset/synth" --export "$out/dataset/annotated.jsonl"
    run dataset-export "$villa" finetune export "$out/dataset/annotated.jsonl" --out "$out/dataset/villa-1k" --format messages --seed 2026 --force
  fi
}

# Paths of the two work folders, measured times and the annotation journal's clock are the only expected
# differences: they are replaced by placeholders in a normalised copy (*.norm) compared instead of the file.
normalise() {
  local out=$1
  while IFS= read -r -d '' f; do
    sed -E -e "s#$out#OUT#g" -e 's/[0-9]+(\.[0-9]+)? ?(s|ms)\b/T/g' -e 's/[0-9]+ layouts\/s/N layouts\/s/g' \
      -e 's/"(seconds|seconds_plan|export|preview|build|plan|total|ms)": [0-9.e-]+/"\1": T/g' \
      -e 's/ [0-9]+\.[0-9]{2}$/ T/' -e 's/"time":"[^"]*"/"time":T/g' "$f" > "$f.norm"
  done < <(find "$out" -type f \( -name '*.stdout' -o -name '*.stderr' -o -name '*.json' -o -name '*.journal.jsonl' \) -print0)
}

produce "$OLD" "$WORK/old"
produce "$NEW" "$WORK/new"
normalise "$WORK/old"
normalise "$WORK/new"

status=0
while IFS= read -r -d '' f; do
  rel=${f#"$WORK/old/"}
  [[ -e "$f.norm" ]] && continue  # compared through its normalised copy
  if [[ ! -e "$WORK/new/$rel" ]]; then echo "missing in new: $rel"; status=1
  elif ! cmp -s "$f" "$WORK/new/$rel"; then echo "differs: $rel"; status=1; fi
done < <(find "$WORK/old" -type f -print0 | sort -z)
while IFS= read -r -d '' f; do
  rel=${f#"$WORK/new/"}
  [[ -e "$WORK/old/$rel" ]] || { echo "only in new: $rel"; status=1; }
done < <(find "$WORK/new" -type f -print0 | sort -z)
echo "compared in $WORK"
exit $status
