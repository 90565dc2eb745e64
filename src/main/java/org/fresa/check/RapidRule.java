package org.fresa.check;

import java.util.List;
import java.util.Optional;
import org.fresa.geom.Vec3;

/**
 * No rapid move meets material the program has not removed: a G00 (an APT {@code RAPID}) whose
 * tool, swept along it, goes below the top of what is left of the stock is a crash, whatever the
 * spindle does. What is left is the stock's box lowered by every feed move before the block
 * ({@link Material}); a rapid down into a pocket the program cleared, to just above its next
 * layer, is allowed, a rapid at a security plane below the stock's top is not.
 *
 * <p>Judged along +Z only (sections along another tool axis, a side of the part, are judged by
 * the other rules), with the tool's bottom taken flat (a drill's pointed) under its radius less one cell of
 * the model's grid ({@link Material#CELL_MM}), and the last written digit of the coordinates
 * allowed for. Where the job states no top of its stock there is nothing to compare.
 */
public final class RapidRule extends Rule {

    public RapidRule() {
        super("rapid", "no rapid move goes into material the program has not removed");
    }

    @Override
    public String broken(Step s, Limits l) {
        Material m = s.material();
        if (s.feedMove() || m == null || !m.known() || !Material.alongZ(s.axis())) {
            return null;
        }
        List<Vec3> p = s.path();
        if (p.isEmpty()) {
            return null;
        }
        ToolLimits tool = l.tool(s.tool());
        double r = tool.radiusMm();
        double allowed = s.dialect().quantumMm() + 1e-6;
        Material.Hit worst = null;
        for (int i = p.size() == 1 ? 0 : 1; i < p.size(); i++) {
            Vec3 a = p.get(Math.max(0, i - 1));
            Optional<Material.Hit> h = m.deepest(a, p.get(i), r, tool);
            if (h.isPresent()
                    && h.get().depthMm() > allowed
                    && (worst == null || h.get().depthMm() > worst.depthMm())) {
                worst = h.get();
            }
        }
        if (worst == null) {
            return null;
        }
        boolean untouched = worst.topZMm() >= m.stockTopZMm();
        return "rapid traverse into the material: at X " + Num.of(worst.at().x()) + " Y "
                + Num.of(worst.at().y())
                + " the tool's bottom goes to Z " + Num.of(worst.at().z()) + " mm, "
                + Num.of(worst.depthMm()) + " mm below the "
                + (untouched ? "stock's top Z " : "material the program left there, at Z ")
                + Num.of(worst.topZMm()) + " mm";
    }
}
