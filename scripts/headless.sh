#!/bin/bash
# Runs a command on a private virtual X display (Xvfb), for ParaView without
# a screen:  scripts/headless.sh pvbatch --no-mpi scripts/render_contact.py DIR
#
# Unlike xvfb-run, it learns that the display is ready from Xvfb itself
# (-displayfd, no signal race that can leave it waiting forever), gives the
# command a time limit, and always stops the display afterwards.
#
# usage: scripts/headless.sh [--timeout SECONDS] command [arguments ...]
#   --timeout  time limit of the command (default 600 s)
# Exit code: the command's; 124 when it ran past the time limit; 125 when
# Xvfb is missing or did not start within 20 s.
# Needs Xvfb (apt-get install xvfb).
set -u
limit=600
case ${1:-} in
  -h|--help) sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
  "") sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2 ;;
  --timeout) limit=$2; shift 2 ;;
esac
if ! command -v Xvfb > /dev/null; then
  echo "Xvfb is not installed (apt-get install xvfb)" >&2
  exit 125
fi

scratch=$(mktemp -d)
Xvfb -displayfd 3 -screen 0 1920x1080x24 -nolisten tcp \
  3> "$scratch/display" > "$scratch/xvfb.log" 2>&1 < /dev/null &
xvfb=$!
stop_display() {
  kill "$xvfb" 2> /dev/null
  wait "$xvfb" 2> /dev/null
  rm -rf "$scratch"
}
trap stop_display EXIT

# Xvfb writes the display number, then a newline, once it accepts clients.
display=""
for _ in $(seq 200); do
  if grep -q '^[0-9]\+$' "$scratch/display" 2> /dev/null; then
    display=$(head -1 "$scratch/display")
    break
  fi
  kill -0 "$xvfb" 2> /dev/null || break
  sleep 0.1
done
if [ -z "$display" ]; then
  echo "Xvfb did not start within 20 s:" >&2
  tail -5 "$scratch/xvfb.log" >&2
  exit 125
fi

DISPLAY=:$display timeout -k 10 "$limit" "$@"
code=$?
[ $code -eq 124 ] && echo "$1 did not finish within $limit s; stopped" >&2
exit $code
