#!/bin/bash
# tools/compare-outputs.sh BEFORE AFTER: the two records of tools/snapshot-outputs.sh, byte for byte
# (PNGs with cmp); in JSON and stdout the timing fields (*_ms, seconds, elapsed) are set aside.
[ $# -eq 2 ] || { echo "usage: tools/compare-outputs.sh BEFORE AFTER" >&2; exit 2; }
a=$1; b=$2; bad=0
diff <(cd "$a" && find . -type f | sort) <(cd "$b" && find . -type f | sort) || bad=1
while read -r p; do
  if [[ $p == *.json || $p == *.stdout ]]; then
    norm() { sed -E 's/"[a-z_]*(_ms|millis|seconds|elapsed)[a-z_]*" *: *[0-9.eE+-]+/"T":0/g' "$1"; }
    cmp -s <(norm "$a/$p") <(norm "$b/$p") || { echo "DIFF $p"; bad=1; }
  else
    cmp -s "$a/$p" "$b/$p" || { echo "DIFF $p"; bad=1; }
  fi
done < <(cd "$a" && find . -type f | sort)
[ $bad = 0 ] && echo "SAME: $(cd "$a" && find . -type f | wc -l) files"
