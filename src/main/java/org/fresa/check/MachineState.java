package org.fresa.check;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Vec3;

/**
 * What the check knows of the machine as it reads a program, block by block or statement by
 * statement: where the tool tip is (NaN until a move states it), the feed and spindle speed in
 * effect (NaN until given), whether the spindle or the jet runs, the tool in the spindle, the
 * section's tool axis, the holes the program has gone straight down so far and what is left of
 * the stock.
 */
abstract class MachineState {
    final Limits limits;
    double x = Double.NaN;
    double y = Double.NaN;
    double z = Double.NaN;
    double feed = Double.NaN;
    double rpm = Double.NaN;
    boolean on;
    int tool;
    Vec3 axis = Vec3.UNIT_Z;
    final List<Pilot> drilled = new ArrayList<>();
    final Material material;

    MachineState(Limits limits) {
        this.limits = limits;
        this.material = Material.of(limits.stock());
    }
}
