#!/bin/sh
# Prints the ten slowest tests of a ctest run from its own timing (the lines "Test #N: NAME ...
# Passed 12.34 sec" of its output, saved in LOG), and with BUDGET the run's wall time beside it.
# Usage: sh .ci/slowest.sh LOG TITLE [BUDGET_SECONDS]
set -eu
log=$1
title=$2
echo "== $title: the ten slowest tests (ctest's seconds)"
sed -n 's/^.*Test *#[0-9]*: \([^ ]*\) .* \([0-9.]*\) sec$/\2 \1/p' "$log" | sort -rn | head -10 |
  awk '{ printf "  %8.2f s  %s\n", $1, $2 }'
total=$(sed -n 's/^Total Test time (real) = *\([0-9.]*\) sec$/\1/p' "$log" | tail -1)
if [ -n "${3:-}" ] && [ -n "$total" ]; then
  echo "== $title: ${total} s wall for the tests (budget ${3} s; informational: a loaded machine is slower)"
fi
