#!/bin/sh
# Lists the functions of lib/, server/ and clients/ longer than LINES lines (default
# 70, one screen), longest first, with the comment line above each so that a reader
# sees at once whether it says why it is long. Needs universal-ctags.
#   scripts/long-functions.sh [LINES]
set -eu
cd "$(dirname "$0")/.."
limit=${1:-70}
ctags -R --languages=C++ --c++-kinds=f --fields=+ne --extras=-'{anonymous}' -o - lib server clients |
  awk -F'\t' -v limit="$limit" '{
    line = ""; end = "";
    for (i = 4; i <= NF; i++) {
      if ($i ~ /^line:/) line = substr($i, 6);
      if ($i ~ /^end:/) end = substr($i, 5);
    }
    if (end != "" && end - line + 1 > limit) printf "%5d %s:%s %s\n", end - line + 1, $2, line, $1;
  }' | sort -rn
