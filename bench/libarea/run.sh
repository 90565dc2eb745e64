#!/usr/bin/env bash
# The whole libarea bench, from the worktree's root or anywhere:
#   bench/libarea/run.sh [DIR] [ALLOWANCE]
# DIR defaults to target/bench; ALLOWANCE, a fraction of the tool diameter, replaces each
# pocket's finishing allowance (0: no pre-finishing pass, as libarea's pocket has none).
# 1. exports the pocket set and Fresa's programs (the Java test LibareaPockets, with the property
#    fresa.bench.out; needs `mvn -o -q test-compile` done),
# 2. makes libarea importable (fetch.sh),
# 3. plans each pocket with libarea, runs both sides' programs through tools/rs274 and measures
#    them (pocket.py): DIR/results.md, DIR/results.csv,
# 4. measures the floor each side leaves uncut (the Java test again, JTS) and writes the table again.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
dir=${1:-$root/target/bench}
allowance=${2:-}
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
rm -rf "$dir/ours"
rm -f "$dir/uncut.csv"
(cd "$root" && mvn -o -B -ntp -q surefire:test -Dtest='LibareaPockets#export' -Dfresa.bench.out="$dir" -Dfresa.bench.allowance="$allowance")
eval "$("$root/bench/libarea/fetch.sh")"
python3.11 "$root/bench/libarea/pocket.py" "$dir" >/dev/null
# 4. the floor each side leaves uncut (JTS, in Java), then the table again with it
(cd "$root" && mvn -o -B -ntp -q surefire:test -Dtest='LibareaPockets#uncut' -Dfresa.bench.out="$dir" -Dfresa.bench.allowance="$allowance")
python3.11 "$root/bench/libarea/pocket.py" "$dir"
