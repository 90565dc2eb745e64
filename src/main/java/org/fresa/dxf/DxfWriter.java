package org.fresa.dxf;

import java.util.List;
import java.util.Locale;
import org.fresa.geom.Arc2;
import org.fresa.geom.Box2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.model.ExactDecimal;

/**
 * Writes contours as an AutoCAD R12 (AC1009) ASCII DXF drawing in millimetres: LINE, ARC and
 * CIRCLE entities on one layer, z = 0.
 *
 * <p>The file carries what common readers expect of a minimal R12 drawing: a HEADER with
 * {@code $ACADVER}, {@code $INSUNITS} = 4 (mm; R12 readers ignore the variable, later ones use
 * it), {@code $MEASUREMENT} = 1 (metric) and the extents; TABLES with the CONTINUOUS line type
 * and the layers; an empty BLOCKS section; ENTITIES; EOF. Group codes are right-aligned in three
 * columns and lines end with CR LF, as AutoCAD writes them. DXF arcs always run counter-clockwise
 * from the start to the end angle, so a clockwise arc is written with its angles swapped.
 * Numbers are the shortest decimals that read back exactly.
 */
public final class DxfWriter {

    private DxfWriter() {}

    /**
     * The drawing of the contours.
     *
     * @param layer the layer name (letters, digits, - and _)
     */
    public static String write(List<Contour> contours, String layer) {
        if (!layer.matches("[A-Za-z0-9_-]{1,31}")) {
            throw new IllegalArgumentException("layer names are letters, digits, - and _: " + layer);
        }
        StringBuilder sb = new StringBuilder();
        Box2 box = null;
        for (Contour c : contours) {
            box = box == null ? c.bounds() : box.union(c.bounds());
        }
        if (box == null) {
            box = new Box2(0, 0, 0, 0);
        }
        group(sb, 0, "SECTION");
        group(sb, 2, "HEADER");
        group(sb, 9, "$ACADVER");
        group(sb, 1, "AC1009");
        group(sb, 9, "$INSBASE");
        point(sb, 10, 0, 0);
        group(sb, 9, "$EXTMIN");
        point(sb, 10, box.minX(), box.minY());
        group(sb, 9, "$EXTMAX");
        point(sb, 10, box.maxX(), box.maxY());
        group(sb, 9, "$LIMMIN");
        group(sb, 10, num(box.minX()));
        group(sb, 20, num(box.minY()));
        group(sb, 9, "$LIMMAX");
        group(sb, 10, num(box.maxX()));
        group(sb, 20, num(box.maxY()));
        group(sb, 9, "$MEASUREMENT");
        group(sb, 70, "1");
        group(sb, 9, "$INSUNITS");
        group(sb, 70, "4");
        group(sb, 0, "ENDSEC");

        group(sb, 0, "SECTION");
        group(sb, 2, "TABLES");
        group(sb, 0, "TABLE");
        group(sb, 2, "LTYPE");
        group(sb, 70, "1");
        group(sb, 0, "LTYPE");
        group(sb, 2, "CONTINUOUS");
        group(sb, 70, "0");
        group(sb, 3, "Solid line");
        group(sb, 72, "65");
        group(sb, 73, "0");
        group(sb, 40, "0.0");
        group(sb, 0, "ENDTAB");
        group(sb, 0, "TABLE");
        group(sb, 2, "LAYER");
        group(sb, 70, "2");
        layer(sb, "0", 7);
        if (!layer.equals("0")) {
            layer(sb, layer, 7);
        }
        group(sb, 0, "ENDTAB");
        group(sb, 0, "ENDSEC");

        group(sb, 0, "SECTION");
        group(sb, 2, "BLOCKS");
        group(sb, 0, "ENDSEC");

        group(sb, 0, "SECTION");
        group(sb, 2, "ENTITIES");
        for (Contour c : contours) {
            for (Curve2 k : c.curves()) {
                entity(sb, k, layer);
            }
        }
        group(sb, 0, "ENDSEC");
        group(sb, 0, "EOF");
        return sb.toString();
    }

    private static void layer(StringBuilder sb, String name, int color) {
        group(sb, 0, "LAYER");
        group(sb, 2, name);
        group(sb, 70, "0");
        group(sb, 62, Integer.toString(color));
        group(sb, 6, "CONTINUOUS");
    }

    private static void entity(StringBuilder sb, Curve2 k, String layer) {
        if (k instanceof Segment2 s) {
            group(sb, 0, "LINE");
            group(sb, 8, layer);
            point(sb, 10, s.start().x(), s.start().y());
            point(sb, 11, s.end().x(), s.end().y());
            return;
        }
        Arc2 a = (Arc2) k;
        if (a.isFullCircle()) {
            group(sb, 0, "CIRCLE");
            group(sb, 8, layer);
            point(sb, 10, a.center().x(), a.center().y());
            group(sb, 40, num(a.radius()));
            return;
        }
        double from = a.ccw() ? a.startAngleRad() : a.endAngleRad();
        double to = a.ccw() ? a.endAngleRad() : a.startAngleRad();
        group(sb, 0, "ARC");
        group(sb, 8, layer);
        point(sb, 10, a.center().x(), a.center().y());
        group(sb, 40, num(a.radius()));
        group(sb, 50, num(degrees(from)));
        group(sb, 51, num(degrees(to)));
    }

    private static double degrees(double rad) {
        double d = Math.toDegrees(rad) % 360;
        return d < 0 ? d + 360 : d;
    }

    private static void point(StringBuilder sb, int code, double x, double y) {
        group(sb, code, num(x));
        group(sb, code + 10, num(y));
        group(sb, code + 20, "0.0");
    }

    private static String num(double d) {
        String s = ExactDecimal.of(d == 0 ? 0.0 : d);
        return s.contains(".") || s.contains("E") ? s : s + ".0";
    }

    private static void group(StringBuilder sb, int code, String value) {
        sb.append(String.format(Locale.ROOT, "%3d", code))
                .append("\r\n")
                .append(value)
                .append("\r\n");
    }
}
