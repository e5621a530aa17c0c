#!/usr/bin/env bash
# Installs the Debian bookworm packages villa builds against, and nothing else.
# Idempotent: it asks dpkg first, so a second run on a ready machine takes about a second.
# Works as root, or through sudo for a normal user.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev libboost-filesystem-dev
  libeigen3-dev libompl-dev libsuitesparse-dev libceres-dev
  libassimp-dev nlohmann-json3-dev libcurl4-openssl-dev
  catch2 libcli11-dev libncurses-dev libtbb-dev libfcl-dev libembree-dev
  libpng-dev zlib1g-dev libstb-dev libcairo2-dev fonts-dejavu-core libcpp-httplib-dev
  sweethome3d-furniture libssl-dev tmux libbullet-dev libmujoco-dev
  slurm-wlm munge
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if [[ ${#missing[@]} -eq 0 ]]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "install-deps: done"
