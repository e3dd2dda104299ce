#!/usr/bin/env bash
# Starts a run and kills it (SIGKILL, from outside, at whatever it is doing
# then, a checkpoint write included) as soon as its statistics file holds
# <rows> rows. Fails if the run ends before.
# usage: kill_when.sh <rows> <statistics file> <log file> <command ...>
set -u
if [ $# -lt 4 ]; then
  sed -n '2,5p' "$0" | sed 's/^# \{0,1\}//'
  [ "${1:-}" = "--help" ] && exit 0 || exit 2
fi
target=$1; statistics=$2; log=$3; shift 3
rows() {
  if [ -f "$statistics" ]; then grep -c -v '^#' "$statistics"; else echo 0; fi
}
"$@" > "$log" 2>&1 &
pid=$!
while kill -0 $pid 2>/dev/null && [ "$(rows)" -lt "$target" ]; do sleep 0.01; done
if ! kill -0 $pid 2>/dev/null; then
  echo "*** the run ended before it could be killed"; exit 1
fi
pkill -KILL -P $pid 2>/dev/null; kill -KILL $pid 2>/dev/null
wait $pid 2>/dev/null
echo "killed after $(rows) rows of statistics"
