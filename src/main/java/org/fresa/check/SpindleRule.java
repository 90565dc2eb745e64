package org.fresa.check;

import java.util.Locale;
import java.util.stream.Collectors;

/**
 * Every cutting move (G01/G02/G03) runs with the spindle on at a speed in the machine's range:
 * after M03/M04 with S in range and before M05 (or a tool change, or the program's end). On a
 * sheet-cutting machine the process's on word (torch, laser, jet) takes the spindle's place. A
 * straight retract along the tool axis cuts nothing and may run with the spindle stopped.
 */
public final class SpindleRule extends Rule {

    public SpindleRule() {
        super(
                "spindle",
                "every cutting move runs with the spindle (or the cutting process) switched on at a speed in range");
    }

    @Override
    public String broken(Step s, Limits l) {
        if (!s.feedMove()) {
            return null;
        }
        if (!l.head().isSpindle()) {
            if (!s.cuttingOn()) {
                return "cutting move with the " + l.head().process() + " off: no "
                        + l.head().on().stream().map(Words.Word::toString).collect(Collectors.joining(" "))
                        + " before it";
            }
            return null;
        }
        if (!s.cuttingOn() && !s.retract()) {
            return "cutting move with the spindle stopped: no M03/M04 with an S word before it, or M05 since";
        }
        if (s.cuttingOn() && !(s.spindleRpm() >= l.spindleMinRpm() && s.spindleRpm() <= l.spindleMaxRpm())) {
            return "cutting move with the spindle at "
                    + (Double.isNaN(s.spindleRpm())
                            ? "no stated speed"
                            : String.format(Locale.ROOT, "S%s", Num.of(s.spindleRpm())))
                    + ": the machine turns "
                    + Num.of(l.spindleMinRpm()) + ".." + Num.of(l.spindleMaxRpm()) + " rpm";
        }
        if (Double.isNaN(s.feedMmPerMin())) {
            return "cutting move with no feed rate (F) stated before it";
        }
        return null;
    }
}
