#!/usr/bin/env bash
# The main job on a bundled example: check it, derive it, and report where the results went.
set -euo pipefail
ramus="$1"
example="$2"
mkdir -p out
"$ramus" info
