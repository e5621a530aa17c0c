#!/usr/bin/env bash
# The main job of `make run`, on built-in defaults: what villa does, end to end, in about a minute.
#   1. generate a furnished villa from a sample request: layout, floor plan with the furniture, scene,
#      furnished 3D villa (glTF), preview picture and report (macro and micro metrics); score its .glb the
#      way other methods' outputs are scored (the paper's micro table); drop it into Bullet and write it for
#      MuJoCo (run there too); furnish a bundled example layout
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
  request="I want a three-story L-shaped villa with a living room, an open-plan kitchen and a dining room on the ground floor, two bedrooms and a bathroom upstairs, and a children's room with a balcony with panoramic windows on the top floor. Put a TV in the living room and bookshelves full of books in the children's room."
  echo "== villa generate: \"$request\""
  "$villa" generate "$request" -o "$out/villa" --seed 7 --force
  if [[ -f "$out/villa/furnished.glb" ]]; then
    echo "== villa eval --scenes --glb $out/villa/furnished.glb (the paper's micro table, as for another method's file)"
    "$villa" eval --scenes --glb "$out/villa/furnished.glb" --scene "$out/villa/scene.json"
    if has physics; then
      echo "== villa physics --mjcf: the villa in Bullet, and written for MuJoCo and run there"
      "$villa" physics "$out/villa/furnished.glb" --mjcf "$out/mjcf" --movers 3
    fi
  fi
  if has furnish; then
    echo "== villa furnish examples/two-floor-house.json"
    "$villa" furnish examples/two-floor-house.json -o "$out/furnished" --seed 7 --force \
      --text "a cosy living room with two armchairs facing the sofa; a desk by the window in the office"
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
[[ -d "$out/villa" ]] && echo "  $out/villa/          furnished villa: layout.json, plan.png, scene.json, furnished.glb, CREDITS, rooms/*.png, preview.png, report.json"
[[ -d "$out/mjcf" ]] && echo "  $out/mjcf/           the villa for MuJoCo: villa.xml and meshes/ (simulate $out/mjcf/villa.xml)"
[[ -d "$out/furnished" ]] && echo "  $out/furnished/      an example layout furnished: scene.json, furnished.glb, plan.png, report.json, CREDITS"
[[ -d "$out/dataset" ]] && echo "  $out/dataset/        synthesized dataset: layouts.jsonl, manifest.json, stats.json, previews"
[[ -d "$out/finetune" ]] && echo "  $out/finetune/       fine-tune export: train/val/test JSONL, dataset_info.json, trainer configs"
[[ -d "$out/examples" ]] && echo "  $out/examples/       floor plans of the bundled examples"
exit 0
