#!/usr/bin/env bash
# The window's speed goal, judged where wall times mean something: the Position tab's live
# reachability for example 2 on the IRB-140, every placement change on screen within 100 ms (the
# 95th percentile and the worst), typed into the real window under Xvfb with the event-thread
# watchdog on. `mvn verify` runs the same test but judges only that each change is shown live:
# on a shared machine the wall time measures the other work. Run on a quiet machine, after a build
# (`mvn -o -q test-compile` or `mvn verify`); the judgement is skipped, never passed, above a load
# of 1.5 per core. Figures: target/live-reach.txt.
set -euo pipefail
cd "$(dirname "$0")/.."
rm -f target/live-reach.txt
status=0
xvfb-run -a -s "-screen 0 1600x1000x24" \
  mvn -o -B -ntp -q surefire:test@event-thread -Dtest=LiveReachGuiTest -Dfresa.judgeSpeed=true \
  -Dsurefire.failIfNoSpecifiedTests=false || status=$?
grep -h "^example 2 on the IRB-140" target/live-reach.txt || true
exit "$status"
