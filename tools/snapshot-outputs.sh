#!/bin/bash
# Records every output of the sample jobs and of the CLI on the samples (stdout, stderr, exit status,
# files) into DIR, so that a refactor can be shown to change no output byte for byte:
#   tools/snapshot-outputs.sh target/fresa.jar /tmp/before   (at the repository root)
[ $# -eq 2 ] || { echo "usage: tools/snapshot-outputs.sh JAR DIR" >&2; exit 2; }
jar=$1; out=$2
rm -rf "$out"; mkdir -p "$out"
f() { java -Djava.awt.headless=true -jar "$jar" "$@"; }
# run NAME ARGS...: stdout, stderr and the exit status of one command
run() { local n=$1; shift; f "$@" >"$out/$n.stdout" 2>"$out/$n.stderr"; echo $? >"$out/$n.rc"; }
for j in samples/jobs/*.xml; do b=$(basename "$j" .xml); run "job-$b" run "$j" --out "$out/job-$b"; done
run cut cut samples/cutting/plate.dxf --out "$out/cut.ngc"
run cut-json cut samples/cutting/plate.dxf --out "$out/cut-json.ngc" --kerf 2 --process laser --lead-in 3 --lead-out 1 --lead line --json
run cut-paper cut samples/cutting/plate.dxf --out "$out/cut-paper.ngc" --paper-mode
tech="--tool-diameter 6 --cut 0.62 --finish 0.13 --z-top 30 --z-bottom 27 --max-depth 3 --rpm 3200 --feed 290 --finish-feed 100"
for p in 7m 7m-compat iso linuxcnc fanuc 840d; do run "pocket-$p" pocket samples/pocket/cavity01.dad --out "$out/pocket-$p.nc" $tech --post $p --json; done
run pocket-rooms pocket samples/pocket/rooms-islands.contour --out "$out/pocket-rooms.nc" --tool-diameter 4 --cut 0.6 --finish 0.1 --z-top 0 --z-bottom -3 --max-depth 1.5 --rpm 3000 --feed 300 --finish-feed 100
run toolpath toolpath samples/stepnc/example2.stp --out "$out/toolpath"
run robot robot samples/stepnc/example2.stp --robot irb140 --out "$out/robot" --robot-table 450,0,350 --table-piece 0,10,0 --formats csv,xml,rapid,krl,png
printf 'x,y,z,roll,pitch,yaw\n500,100,500,0,180,0\n450,0,600,0,150,0\n' >"$out/targets.csv"
run ik ik "$out/targets.csv" --robot irb140 --out "$out/ik" --all
run grade grade samples/grading/sole-40.contour --out "$out/grade" --base-size 40 --sizes 38-42 --system br --json
run sole sole samples/jobs/sole-men40.xml --out "$out/sole"
run stepnc stepnc samples/stepnc/example2.stp
run stepnc-json stepnc samples/stepnc/example2.stp --json
run posts posts
run robots robots
run help --help
for c in gui run stepnc toolpath robot pocket cut grade sole ik robots posts bench; do run "help-$c" $c --help; done
# bad input: one message, exit 2, nothing written
printf 'x,y,z,roll,pitch,yaw\n500,0,500,0,180\n' >"$out/bad-targets.csv"
run bad-ik ik "$out/bad-targets.csv" --robot irb140 --out "$out/bad-ik"
printf '0\nSECTION\n2\nENTITIES\n0\nLINE\n10\nabc\n' >"$out/bad.dxf"
run bad-cut cut "$out/bad.dxf" --out "$out/bad-cut.ngc"
run bad-pocket pocket samples/pocket/cavity01.dad --out "$out/bad-pocket.nc" $tech --post nosuch
run bad-grade grade samples/grading/sole-40.contour --out "$out/bad-grade" --base-size 40 --sizes 44-38 --system br
run bad-run run samples/pocket/cavity01.dad --out "$out/bad-run"
run bad-stepnc stepnc samples/pocket/cavity01.dad
run bad-option cut samples/cutting/plate.dxf --out "$out/bad-opt.ngc" --kerf abc
run bad-missing toolpath /nonexistent.stp --out "$out/bad-missing"
# the STEP-NC toolpaths of every sample and of the reference corpus (FRESA_STEPNC_CORPUS, when present)
corpus=${FRESA_STEPNC_CORPUS:-/work/shared/corpus/stepnc}
for p in samples/stepnc/*.stp "$corpus"/*/*; do
  [ -f "$p" ] || continue
  n=toolpath-$(basename "$(dirname "$p")")-$(basename "$p" | tr -c 'A-Za-z0-9.\n-' '_')
  run "$n" toolpath "$p" --out "$out/$n"
  # files whose spindle speed and cutting speed disagree are refused above: planned here from the cutting speed
  run "$n-trust" toolpath "$p" --out "$out/$n-trust" --trust-cutting-speed
done
# the temporary dir name appears in messages: make it neutral
grep -rl --exclude='*.png' "$out" "$out" 2>/dev/null | xargs -r sed -i "s#$out#OUT#g"
