package org.fresa.dxf;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import org.fresa.geom.Curve2;

/**
 * The plane geometry of a DXF drawing's model space, in millimetres, with blocks expanded,
 * OCS arcs turned into world arcs and ellipses and splines replaced by arcs.
 *
 * @param source the file name, for messages
 * @param units the units the drawing was read in (after any override)
 * @param mmPerUnit the scale applied to every coordinate
 * @param layers the curves of each layer, in file order (lines and exact arcs, in mm)
 * @param warnings one sentence each: broken entities (by handle and line), unit guesses, limits
 * @param ignored how many entities of each non-geometric type (TEXT, HATCH, ...) were skipped
 */
public record DxfDrawing(
        String source,
        DxfUnits units,
        double mmPerUnit,
        Map<String, List<Curve2>> layers,
        List<String> warnings,
        Map<String, Integer> ignored) {

    public DxfDrawing {
        Objects.requireNonNull(source, "source");
        Objects.requireNonNull(units, "units");
        Map<String, List<Curve2>> copy = new LinkedHashMap<>();
        layers.forEach((k, v) -> copy.put(k, List.copyOf(v)));
        layers = Collections.unmodifiableMap(copy);
        warnings = List.copyOf(warnings);
        ignored = Collections.unmodifiableMap(new LinkedHashMap<>(ignored));
    }

    /** Every curve of every layer. */
    public List<Curve2> curves() {
        List<Curve2> all = new ArrayList<>();
        layers.values().forEach(all::addAll);
        return all;
    }

    public int curveCount() {
        int n = 0;
        for (List<Curve2> l : layers.values()) {
            n += l.size();
        }
        return n;
    }

    public int ignoredCount() {
        int n = 0;
        for (int v : ignored.values()) {
            n += v;
        }
        return n;
    }
}
