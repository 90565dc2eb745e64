package org.fresa.dxf;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Arc2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.junit.jupiter.api.Test;

class DxfWriterTest {

    /** A closed contour with a line, a clockwise arc and a counter-clockwise arc. */
    private static Contour sample() {
        Vec2 a = new Vec2(0, 0);
        Vec2 b = new Vec2(40, 0);
        Vec2 c = new Vec2(40, 20);
        return new Contour(List.of(
                new Segment2(a, b),
                new Arc2(new Vec2(40, 10), b, c, true),
                new Arc2(new Vec2(20, 20.0 - Math.sqrt(400 - 400.0)), c, new Vec2(0, 20), true),
                new Segment2(new Vec2(0, 20), a)));
    }

    private static List<String[]> pairs(String dxf) {
        String[] lines = dxf.split("\r\n", -1);
        List<String[]> out = new ArrayList<>();
        for (int i = 0; i + 1 < lines.length; i += 2) {
            out.add(new String[] {lines[i].trim(), lines[i + 1]});
        }
        return out;
    }

    @Test
    void theFileIsAnR12DrawingInMillimetresWithHeaderTablesAndEntities() {
        String dxf = DxfWriter.write(List.of(sample()), "OUTLINE");
        List<String[]> p = pairs(dxf);
        String codes = String.join(" ", p.stream().map(x -> x[0] + "=" + x[1]).toList());
        assertAll(
                () -> assertTrue(codes.startsWith("0=SECTION 2=HEADER 9=$ACADVER 1=AC1009")),
                () -> assertTrue(codes.contains("9=$INSUNITS 70=4")),
                () -> assertTrue(codes.contains("0=TABLE 2=LAYER")),
                () -> assertTrue(codes.contains("2=OUTLINE")),
                () -> assertTrue(codes.endsWith("0=ENDSEC 0=EOF")),
                () -> assertEquals(
                        2,
                        p.stream()
                                .filter(x -> x[0].equals("0") && x[1].equals("LINE"))
                                .count()),
                () -> assertEquals(
                        2,
                        p.stream()
                                .filter(x -> x[0].equals("0") && x[1].equals("ARC"))
                                .count()),
                () -> assertTrue(dxf.endsWith("EOF\r\n")),
                () -> assertTrue(dxf.startsWith("  0\r\nSECTION\r\n")));
    }

    @Test
    void arcsReadBackWithTheirEndPointsWhateverTheirSense() {
        Arc2 ccw = new Arc2(new Vec2(1, 2), new Vec2(11, 2), new Vec2(1, 12), true);
        Arc2 cw = ccw.reversed();
        for (Arc2 arc : List.of(ccw, cw)) {
            List<String[]> p = pairs(DxfWriter.write(
                    List.of(new Contour(List.<Curve2>of(arc, new Segment2(arc.end(), arc.start())))), "L1"));
            int i = 0;
            while (!(p.get(i)[0].equals("0") && p.get(i)[1].equals("ARC"))) {
                i++;
            }
            double cx = 0;
            double cy = 0;
            double r = 0;
            double a0 = 0;
            double a1 = 0;
            for (int k = i + 1; !p.get(k)[0].equals("0"); k++) {
                double v = p.get(k)[0].equals("8") ? 0 : Double.parseDouble(p.get(k)[1]);
                switch (p.get(k)[0]) {
                    case "10" -> cx = v;
                    case "20" -> cy = v;
                    case "40" -> r = v;
                    case "50" -> a0 = v;
                    case "51" -> a1 = v;
                    default -> {}
                }
            }
            Vec2 from = new Vec2(cx, cy).plus(Vec2.ofAngle(Math.toRadians(a0)).times(r));
            Vec2 to = new Vec2(cx, cy).plus(Vec2.ofAngle(Math.toRadians(a1)).times(r));
            // DXF arcs run counter-clockwise from 50 to 51
            Vec2 ccwStart = arc.ccw() ? arc.start() : arc.end();
            Vec2 ccwEnd = arc.ccw() ? arc.end() : arc.start();
            assertEquals(0, from.distance(ccwStart), 1e-9);
            assertEquals(0, to.distance(ccwEnd), 1e-9);
        }
    }

    @Test
    void fullCirclesAreCircleEntities() {
        String dxf = DxfWriter.write(List.of(new Contour(List.of(Arc2.circle(new Vec2(5, 5), 3, false)))), "H");
        assertTrue(
                dxf.contains("  0\r\nCIRCLE\r\n  8\r\nH\r\n 10\r\n5.0\r\n 20\r\n5.0\r\n 30\r\n0.0\r\n 40\r\n3.0\r\n"));
    }
}
