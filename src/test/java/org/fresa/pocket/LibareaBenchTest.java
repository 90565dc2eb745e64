package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.fresa.geom.Vec3;
import org.fresa.post.Rs274;
import org.fresa.testing.InterpreterCheck;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Fresa's figures on the libarea bench's pockets ({@link LibareaPockets}) stay at or under the
 * figures recorded in {@code libarea-bench.csv} (docs/pocket-vs-libarea.md): rapids, rapid
 * length, motion blocks and machining time, summed over the set and measured from LinuxCNC's
 * moves as bench/libarea/pocket.py measures them. The table holds libarea's figures beside
 * ours, recorded with libarea by the bench; this test needs no libarea.
 */
class LibareaBenchTest {

    static final double FEED_MM_PER_MIN = 300;
    static final double RAPID_MM_PER_MIN = 5000;

    /** The figures of one program: rapids, rapid length, motion blocks, feed length, minutes. */
    record Figures(int rapids, double rapidMm, int blocks, double feedMm, double minutes) {
        Figures plus(Figures o) {
            return new Figures(
                    rapids + o.rapids, rapidMm + o.rapidMm, blocks + o.blocks, feedMm + o.feedMm, minutes + o.minutes);
        }
    }

    /** As pocket.py's measure: from the first move that leaves the clearance height. */
    static Figures measure(List<Rs274.Canon> moves, double clearanceZ) {
        Vec3 at = Vec3.ZERO;
        boolean approach = true;
        int rapids = 0;
        int blocks = 0;
        double rapidMm = 0;
        double feedMm = 0;
        for (Rs274.Canon m : moves) {
            if (m.kind().equals("dwell")) {
                continue;
            }
            Vec3 e = m.end();
            double length;
            if (m.kind().equals("arc")) {
                double cx = m.center().x();
                double cy = m.center().y();
                double r = Math.hypot(at.x() - cx, at.y() - cy);
                double a0 = Math.atan2(at.y() - cy, at.x() - cx);
                double a1 = Math.atan2(e.y() - cy, e.x() - cx);
                double sweep = m.rotation() > 0 ? a1 - a0 : a0 - a1;
                sweep = ((sweep % (2 * Math.PI)) + 2 * Math.PI) % (2 * Math.PI);
                if (sweep < 1e-9) {
                    sweep = 2 * Math.PI;
                }
                sweep += 2 * Math.PI * (Math.abs(m.rotation()) - 1);
                length = Math.hypot(r * sweep, e.z() - at.z());
            } else {
                length = at.distance(e);
            }
            at = e;
            approach = approach && m.kind().equals("rapid") && e.z() >= clearanceZ - 1e-6;
            if (approach) {
                continue;
            }
            blocks++;
            if (m.kind().equals("rapid")) {
                rapids++;
                rapidMm += length;
            } else {
                feedMm += length;
            }
        }
        return new Figures(rapids, rapidMm, blocks, feedMm, feedMm / FEED_MM_PER_MIN + rapidMm / RAPID_MM_PER_MIN);
    }

    /** The recorded totals by side ("ours", "libarea"). */
    static Map<String, Figures> recorded() throws IOException {
        Map<String, Figures> out = new HashMap<>();
        try (InputStream in = LibareaBenchTest.class.getResourceAsStream("libarea-bench.csv")) {
            for (String line : new String(in.readAllBytes(), StandardCharsets.UTF_8).split("\n")) {
                if (line.isBlank() || line.startsWith("#") || line.startsWith("side")) {
                    continue;
                }
                String[] f = line.trim().split(",");
                out.put(
                        f[0],
                        new Figures(
                                Integer.parseInt(f[1]),
                                Double.parseDouble(f[2]),
                                Integer.parseInt(f[3]),
                                Double.parseDouble(f[4]),
                                Double.parseDouble(f[5])));
            }
        }
        return out;
    }

    @Test
    @InterpreterCheck
    void oursStayAtOrUnderTheRecordedFigures(@TempDir Path dir) throws Exception {
        assumeTrue(Rs274.available(), Rs274.whyNot());
        Figures total = new Figures(0, 0, 0, 0, 0);
        List<String> per = new ArrayList<>();
        for (LibareaPockets.Bench b : LibareaPockets.pockets()) {
            Path f = dir.resolve(b.name() + ".ngc");
            Files.writeString(f, LibareaPockets.program(b));
            Rs274.Result res = Rs274.run(f, b.tech().toolDiameterMm());
            assertTrue(res.exitStatus() == 0, b.name() + ": " + Rs274.log(res));
            Figures fig = measure(res.motions(), b.tech().zTopMm() + 5);
            per.add(b.name() + " " + fig);
            total = total.plus(fig);
        }
        Map<String, Figures> rec = recorded();
        Figures ours = rec.get("ours");
        Figures libarea = rec.get("libarea");
        System.out.printf(
                Locale.ROOT,
                "libarea bench: G0 %d (libarea %d), rapids %.1f mm (%.1f), blocks %d (%d), feed %.1f mm (%.1f),"
                        + " time %.3f min (%.3f, x%.3f)%n",
                total.rapids(),
                libarea.rapids(),
                total.rapidMm(),
                libarea.rapidMm(),
                total.blocks(),
                libarea.blocks(),
                total.feedMm(),
                libarea.feedMm(),
                total.minutes(),
                libarea.minutes(),
                total.minutes() / libarea.minutes());
        String why = "now " + total + ", recorded " + ours + "; per pocket " + per;
        assertTrue(total.rapids() <= ours.rapids(), "more rapids: " + why);
        assertTrue(total.rapidMm() <= ours.rapidMm() + 0.5, "longer rapids: " + why);
        assertTrue(total.blocks() <= ours.blocks(), "more blocks: " + why);
        assertTrue(total.minutes() <= ours.minutes() + 0.005, "longer machining time: " + why);
    }
}
