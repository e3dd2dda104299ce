#!/bin/bash
# Renders a run's output with scripts/render_contact.py (or the ParaView
# script of scripts/ given third, which takes the same --out, --name and
# --size) on a virtual display (scripts/headless.sh) and checks that the
# picture was written. Skipped (exit code 77) where ParaView or Xvfb is not
# installed: they are optional (apt-get install paraview python3-paraview
# xvfb).
#
# usage: render_contact.sh <project source folder> <output directory> [script]
set -u
if [ $# -lt 2 ] || [ $# -gt 3 ] || [ "$1" = "--help" ]; then
  sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'
  [ $# -eq 1 ] && exit 0 || exit 2
fi
script=${3:-render_contact.py}
for tool in pvbatch Xvfb; do
  if ! command -v $tool > /dev/null; then
    echo "SKIPPED: $tool is not installed (apt-get install paraview python3-paraview xvfb)"
    exit 77
  fi
done
folder=$(mktemp -d)
# The output goes to a file, not through a pipe: nothing the renderer
# leaves behind can keep this script waiting.
for attempt in 1 2 3; do
  "$1/scripts/headless.sh" --timeout 120 pvbatch --no-mpi \
    "$1/scripts/$script" "$2" --out "$folder" --name render \
    --size 900x300 > "$folder/log" 2>&1 < /dev/null
  code=$?
  grep -v '^\s*$' "$folder/log" | tail -5
  if grep -q "No module named 'paraview'" "$folder/log"; then
    echo "SKIPPED: ParaView's Python is not installed (apt-get install python3-paraview)"
    exit 77
  fi
  # 124: past the time limit; a hang is not retried
  [ $code -eq 0 ] || [ $code -eq 124 ] && break
  echo "attempt $attempt failed (exit code $code)"
  sleep 2
done
size=$(stat -c %s "$folder/render.png" 2>/dev/null || echo 0)
echo "$folder/render.png: $size bytes"
[ $code -eq 0 ] && [ "$size" -gt 10000 ]
