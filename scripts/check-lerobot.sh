#!/usr/bin/env bash
# `make check-lerobot` (not part of `make test`: it installs LeRobot, torch with it, about
# 8 GB and 6 minutes the first time): LeRobot itself loads the dataset `bsv so101-dataset`
# writes from the scripted session of tests/so101/session/, offline, and reads every frame
# (tests/lerobot/load_with_lerobot.py). LeRobot 0.6 needs Python 3.12 or newer: the first of
# python3.13, python3.12 or a pyenv 3.12+ found makes .venv-lerobot; without one, python3
# gets the newest LeRobot pip offers it (0.4.x on 3.11, also format v3.0).
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

LEROBOT_VERSION=0.6.1
VENV=.venv-lerobot

say() { printf '\033[1m[check-lerobot]\033[0m %s\n' "$*"; }

python=""
for candidate in python3.13 python3.12 "$HOME"/.pyenv/versions/3.1[2-9]*/bin/python3; do
  if command -v "$candidate" >/dev/null 2>&1; then
    python=$(command -v "$candidate")
    break
  fi
done
spec="lerobot[dataset]==$LEROBOT_VERSION"
if [[ -z "$python" ]]; then
  python=python3
  spec="lerobot"
  say "no Python 3.12+: LeRobot $LEROBOT_VERSION needs it; installing the newest LeRobot for $($python --version)"
fi
if [[ ! -x "$VENV/bin/python" ]] || ! "$VENV/bin/python" -c 'import lerobot, datasets' 2>/dev/null \
  || { [[ "$spec" != lerobot ]] && [[ "$("$VENV/bin/python" -c 'import lerobot; print(lerobot.__version__)')" != "$LEROBOT_VERSION" ]]; }; then
  say "installing $spec into $VENV with $($python --version) (torch comes along: about 8 GB, 6 minutes)"
  rm -rf "$VENV"
  "$python" -m venv "$VENV"
  "$VENV/bin/pip" install -q --upgrade pip
  "$VENV/bin/pip" install -q "$spec"
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
root="$work/so101-practice"
say "writing the scripted session's dataset with bsv so101-dataset"
cargo run --locked --quiet --bin bsv -- so101-dataset tests/so101/session/so101_episode_*.csv --out "$root"
say "loading it with LeRobotDataset, offline, frame by frame"
HF_HUB_OFFLINE=1 HF_DATASETS_OFFLINE=1 HF_LEROBOT_HOME="$work/home" HF_HOME="$work/hf" \
  "$VENV/bin/python" tests/lerobot/load_with_lerobot.py "$root" bsv/so101-practice
say "LeRobot loaded every frame"
