#!/usr/bin/env bash
# The main job of `make run`, on built-in defaults: what villa does, end to end, in about a minute.
#   1. generate a villa from a sample request: layout, floor plan, 3D building (glTF) and a preview picture,
#      then furnish it: every room planned, given assets and solved (scene, furnished glTF, report)
#   2. synthesize a small training dataset with previews, auto-annotate it and export it for fine-tuning
#   3. validate and render the bundled example layouts
# Prints where every output is.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
villa=$(realpath "${1:-$root/build/cli/villa}")
out=$(realpath -m "${2:-$root/out}")
cd "$root"
mkdir -p "$out"
has() { "$villa" "$1" --help >/dev/null 2>&1; }

if has generate; then
  request="I want a three-story L-shaped villa with a living room, an open-plan kitchen and a dining room on the ground floor, two bedrooms and a bathroom upstairs, and a children's room with a balcony with panoramic windows on the top floor."
  echo "== villa generate: \"$request\""
  "$villa" generate "$request" -o "$out/villa" --seed 7 --force
  if has furnish; then
    echo "== villa furnish $out/villa/layout.json"
    "$villa" furnish "$out/villa/layout.json" -o "$out/furnished" --seed 7 --force \
      --text "a cosy living room with two armchairs and bookshelves full of books"
  fi
fi

if has synth; then
  echo "== villa synth: 60 layouts (2:4:4 floors) with 4 previews"
  "$villa" synth --count 60 --seed 1 --out "$out/dataset" --previews 4 --force
  if has annotate; then
    "$villa" annotate "$out/dataset" --auto
    "$villa" annotate "$out/dataset" --export "$out/dataset/annotated.jsonl" --force
    if has finetune; then
      "$villa" finetune export "$out/dataset/annotated.jsonl" --out "$out/finetune" --force
    fi
  fi
fi

echo "== villa validate examples/*.json"
"$villa" validate examples/*.json
if has render; then
  mkdir -p "$out/examples"
  for f in examples/*.json; do
    name=$(basename "$f" .json)
    "$villa" render "$f" -o "$out/examples/$name.png" --force
  done
fi

echo
echo "outputs:"
[[ -d "$out/villa" ]] && echo "  $out/villa/          generated villa: layout.json, plan.png, building.glb, preview.png, report.json"
[[ -d "$out/furnished" ]] && echo "  $out/furnished/      the villa furnished: scene.json, furnished.glb, report.json, CREDITS"
[[ -d "$out/dataset" ]] && echo "  $out/dataset/        synthesized dataset: layouts.jsonl, manifest.json, stats.json, previews"
[[ -d "$out/finetune" ]] && echo "  $out/finetune/       fine-tune export: train/val/test JSONL, dataset_info.json, trainer configs"
[[ -d "$out/examples" ]] && echo "  $out/examples/       floor plans of the bundled examples"
exit 0
