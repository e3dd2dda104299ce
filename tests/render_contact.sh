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
if ! pvbatch --version > /dev/null 2>&1 ||
   ! xvfb-run -a pvbatch -c "import paraview.simple" > /dev/null 2>&1; then
  echo "SKIPPED: ParaView's Python is not installed (apt-get install python3-paraview)"
  exit 77
fi
picture=$(mktemp -d)/render
xvfb-run -a pvbatch "$1/scripts/render_contact.py" "$2" --out "$(dirname "$picture")" \
  --name render --size 900x300 || exit 1
size=$(stat -c %s "$picture.png" 2>/dev/null || echo 0)
echo "$picture.png: $size bytes"
[ "$size" -gt 10000 ]
