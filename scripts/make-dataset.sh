#!/usr/bin/env bash
# The reference fine-tuning dataset, datasets/villa-1k, regenerated end to end:
#   villa synth (1,000 layouts, floors 2:4:4, fixed seed) -> villa annotate --auto -> --export
#   -> villa finetune export (messages format) -> villa finetune check.
# Every step is deterministic, so the result is byte-identical to the committed files; the script says
# whether it is (git diff) and exits 1 when the export fails its check.
# Usage: scripts/make-dataset.sh PATH/TO/villa   (`make dataset` passes build/cli/villa)
set -euo pipefail

if [[ $# -ne 1 ]]; then
  echo "usage: $0 PATH/TO/villa" >&2
  exit 2
fi
VILLA=$(realpath "$1")
if [[ ! -x "$VILLA" ]]; then
  echo "make-dataset: $1 is not an executable villa binary (run make build first)" >&2
  exit 2
fi

ROOT=$(cd "$(dirname "$0")/.." && pwd)
SEED=2026          # the recipe: change it and the dataset is a different one
COUNT=1000
FLOORS=2:4:4
OUT="$ROOT/datasets/villa-1k"

WORK=$(mktemp -d "${TMPDIR:-/tmp}/villa-dataset.XXXXXX")
trap 'rm -rf "$WORK"' EXIT

echo "== villa synth --count $COUNT --floors $FLOORS --seed $SEED"
"$VILLA" synth --count "$COUNT" --floors "$FLOORS" --seed "$SEED" --out "$WORK/synth"
echo "== villa annotate --auto (drafted labels and descriptions; no person verifies them)"
"$VILLA" annotate "$WORK/synth" --auto
"$VILLA" annotate "$WORK/synth" --export "$WORK/annotated.jsonl"
echo "== villa finetune export -> ${OUT#$ROOT/}"
# --force: this folder belongs to the recipe; its files are replaced by the regenerated ones.
"$VILLA" finetune export "$WORK/annotated.jsonl" --out "$OUT" --format messages --seed "$SEED" --force
echo "== villa finetune check"
"$VILLA" finetune check "$OUT"

if git -C "$ROOT" rev-parse --is-inside-work-tree > /dev/null 2>&1 &&
   git -C "$ROOT" ls-files --error-unmatch "${OUT#$ROOT/}/train.jsonl" > /dev/null 2>&1; then
  if git -C "$ROOT" diff --quiet -- "${OUT#$ROOT/}"; then
    echo "datasets/villa-1k: byte-identical to the committed dataset"
  else
    echo "datasets/villa-1k: differs from the committed dataset:" >&2
    git -C "$ROOT" diff --stat -- "${OUT#$ROOT/}" >&2
  fi
fi
