#!/bin/bash
# Renders every shipped scene (parameters/*.prm) to doc/figures/<scene>.png:
# runs each scene with the built program in a scratch folder, then
# scripts/render_contact.py on a virtual display (the time with the most
# contact; ironing_2d, strip_drawing_2d and the billets at their last),
# and for 2D scenes scripts/plot_contact_profile.py
# (doc/figures/<scene>-profile.png), for axisymmetric ones also
# scripts/revolve_section.py (doc/figures/<scene>-revolved.png). A
# ParaView state of each run (contact.pvsm) is saved in its output folder,
# next to the data it names: open it in the GUI (File > Load State).
#
# usage: scripts/make_gallery.sh [--build build] [--out doc/figures] [scene ...]
# Needs ParaView and Xvfb (apt-get install paraview python3-paraview xvfb).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build
out=$root/doc/figures
scenes=()
while [ $# -gt 0 ]; do
  case $1 in
    -h|--help) sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    --build) build=$(cd "$2" && pwd); shift 2 ;;
    --out) mkdir -p "$2"; out=$(cd "$2" && pwd); shift 2 ;;
    *) scenes+=("$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"); shift ;;
  esac
done
if [ ${#scenes[@]} -eq 0 ]; then
  scenes=("$root"/parameters/*.prm)
fi
for tool in pvbatch Xvfb; do
  command -v $tool > /dev/null || {
    echo "$tool is missing: apt-get install paraview python3-paraview xvfb" >&2
    exit 1
  }
done
# A Python with matplotlib for the profile plots (Debian's, by default).
python=python3
"$python" -c "import matplotlib" 2> /dev/null || python=/usr/bin/python3
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
scratch=$(mktemp -d /tmp/gallery-XXXXXX)
mkdir -p "$out"
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .prm)
  mkdir -p "$scratch/$name"
  echo "== $name"
  # The scene as shipped (the 2D ones write the CSV tables of the profile).
  (cd "$scratch/$name" && "$build/contact" "$scene" > run.log 2>&1) || { echo "the run failed: $scratch/$name/run.log" >&2; exit 1; }
  directory=$(dirname "$(find "$scratch/$name" -name solution.pvd | head -1)")
  # A scene whose point is where its load ends (the die at the end of its
  # path) is drawn at its last time; the others at the most contact.
  times=contact
  case $name in ironing_2d|strip_drawing_2d|billet_upsetting*) times=last ;; esac
  "$root/scripts/headless.sh" pvbatch --no-mpi "$root/scripts/render_contact.py" "$directory" \
    --out "$out" --name "$name" --times $times --state "$directory/contact.pvsm" 2>&1 | grep '^wrote' || {
      echo "rendering $name failed" >&2; exit 1; }
  # 2D: the pressure and traction along the contact boundary as a plot.
  if grep -q "^ *set Dimension *= *2" "$directory/parameters.prm" \
      && ls "$directory"/contact-*.csv > /dev/null 2>&1; then
    "$python" "$root/scripts/plot_contact_profile.py" "$directory" \
      --out "$out/$name-profile.png" | grep '^wrote' || {
        echo "the profile plot of $name failed" >&2; exit 1; }
  fi
  # Axisymmetric: the section turned about its axis, the bodies it stands for.
  if grep -q "^ *set Two-dimensional model *= *axisymmetric" "$directory/parameters.prm"; then
    "$root/scripts/headless.sh" pvbatch --no-mpi "$root/scripts/revolve_section.py" "$directory" \
      --out "$out" --name "$name-revolved" 2>&1 | grep '^wrote' || {
        echo "the revolved picture of $name failed" >&2; exit 1; }
  fi
done
echo "pictures in $out (runs in $scratch)"
