package org.fresa.post;

import java.io.IOException;
import java.io.Writer;
import java.util.Locale;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;

/**
 * A minimal RS274/NGC (LinuxCNC) writer used by the pocket module until the shared generic posts
 * are merged: G17 G21 G90 G94, G00/G01/G02/G03 with incremental I/J, feeds restated when they
 * change, 4 decimals, {@code Locale.ROOT}.
 */
public final class PocketRs274Fallback implements NcPost {

    @Override
    public String name() {
        return "linuxcnc";
    }

    @Override
    public String description() {
        return "LinuxCNC RS274/NGC (pocket fallback)";
    }

    @Override
    public void write(Toolpath path, String programName, Writer out) throws IOException {
        String name = programName.replaceAll("[()]", "");
        out.write("(" + name + ")\n");
        out.write("G17 G21 G90 G94 G40 G49 G80\n");
        for (ToolpathSection s : path.sections()) {
            out.write(String.format(Locale.ROOT, "T%d M06\n", s.toolNumber()));
            if (s.spindleRpm() > 0) {
                out.write(String.format(Locale.ROOT, "S%.0f M03\n", s.spindleRpm()));
            }
            Vec3 cur = s.start();
            out.write("G00 Z" + f(cur.z()) + "\n");
            out.write("G00 X" + f(cur.x()) + " Y" + f(cur.y()) + "\n");
            double feed = -1;
            for (Move m : s.moves()) {
                Vec3 e = m.end();
                if (m instanceof Move.Rapid) {
                    out.write("G00" + coords(cur, e) + "\n");
                } else if (m instanceof Move.Linear l) {
                    String fw = l.feedMmPerMin() != feed ? " F" + f(l.feedMmPerMin()) : "";
                    feed = l.feedMmPerMin();
                    out.write("G01" + coords(cur, e) + fw + "\n");
                } else if (m instanceof Move.Circular c) {
                    String fw = c.feedMmPerMin() != feed ? " F" + f(c.feedMmPerMin()) : "";
                    feed = c.feedMmPerMin();
                    out.write((c.ccw() ? "G03" : "G02") + " X" + f(e.x()) + " Y" + f(e.y())
                            + (e.z() != cur.z() ? " Z" + f(e.z()) : "")
                            + " I" + f(c.center().x() - cur.x()) + " J" + f(c.center().y() - cur.y()) + fw + "\n");
                }
                cur = e;
            }
        }
        out.write("M05\nM02\n");
    }

    private static String coords(Vec3 from, Vec3 to) {
        StringBuilder sb = new StringBuilder();
        if (to.x() != from.x() || to.y() != from.y()) {
            sb.append(" X").append(f(to.x())).append(" Y").append(f(to.y()));
        }
        if (to.z() != from.z() || sb.length() == 0) {
            sb.append(" Z").append(f(to.z()));
        }
        return sb.toString();
    }

    private static String f(double v) {
        String s = String.format(Locale.ROOT, "%.4f", v);
        return s.equals("-0.0000") ? "0.0000" : s;
    }
}
