#!/bin/bash
# Renders a run's output with scripts/render_contact.py under Xvfb and checks
# that the picture was written. Skipped (exit code 77) where ParaView or
# Xvfb is not installed: they are optional (apt-get install paraview
# python3-paraview xvfb).
#
# usage: render_contact.sh <project source folder> <output directory>
set -u
if [ $# -ne 2 ] || [ "$1" = "--help" ]; then
  sed -n '2,7p' "$0" | sed 's/^# \{0,1\}//'
  [ $# -eq 1 ] && exit 0 || exit 2
fi
for tool in pvbatch xvfb-run; do
  if ! command -v $tool > /dev/null; then
    echo "SKIPPED: $tool is not installed (apt-get install paraview python3-paraview xvfb)"
    exit 77
  fi
done
folder=$(mktemp -d)
# Xvfb can be slow to come up on a loaded machine ("bad X server
# connection"): try three times.
for attempt in 1 2 3; do
  log=$(xvfb-run -a -e /dev/stdout pvbatch "$1/scripts/render_contact.py" "$2" \
          --out "$folder" --name render --size 900x300 2>&1)
  code=$?
  echo "$log" | grep -v '^\s*$' | tail -5
  if echo "$log" | grep -q "No module named 'paraview'"; then
    echo "SKIPPED: ParaView's Python is not installed (apt-get install python3-paraview)"
    exit 77
  fi
  [ $code -eq 0 ] && break
  echo "attempt $attempt failed (exit code $code)"
  sleep 2
done
size=$(stat -c %s "$folder/render.png" 2>/dev/null || echo 0)
echo "$folder/render.png: $size bytes"
[ $code -eq 0 ] && [ "$size" -gt 10000 ]
