package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fresa.geom.Contour;
import org.fresa.geom.EnclosingCircle;
import org.fresa.geom.Vec2;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;
import org.fresa.pocket.compat.Sinumerik7MPost;
import org.junit.jupiter.api.Test;

/**
 * The single-contour engines (the thesis's offset passes, the zigzag strategy, the corrected 7M
 * post) go down, for a cutter that does not cut at its centre, only along courses that move its
 * centre by half its radius ({@link Entries#movesTheCentreOver}, the rule {@link EntryCoreTest}
 * holds the region engine to): a zig-zag ramp forth and back along a pass shorter than the tool
 * radius keeps the core over the same material all the way down.
 */
class SingleContourEntryCoreTest {

    static final String[] THESIS = {
        "examplepart", "cavity01", "cavity02", "cavity03", "cavity04", "cavity05", "cavity06", "cavity07"
    };

    /** What the descents of a set of programs came to. */
    static final class Tally {
        int programs;
        int refused;
        int unrecognised;
        int entries;
        final List<String> unsafe = new ArrayList<>();
        double worstMm = Double.POSITIVE_INFINITY;

        void check(String what, List<List<Vec2>> runs, double radiusMm) {
            programs++;
            for (List<Vec2> run : runs) {
                entries++;
                if (!Entries.movesTheCentreOver(run, radiusMm)) {
                    double r = EnclosingCircle.radiusMm(run);
                    worstMm = Math.min(worstMm, r);
                    unsafe.add(String.format(
                            Locale.ROOT,
                            "%s: within %.3f mm about X%.3f Y%.3f (R %.1f)",
                            what,
                            r,
                            run.get(0).x(),
                            run.get(0).y(),
                            radiusMm));
                }
            }
        }

        void refusal(String what, ToolTooLargeException e) {
            assertTrue(e.getMessage().contains("X"), "the refusal names the place: " + e.getMessage());
            refused++;
            System.out.println("refused: " + what + ": " + e.getMessage());
        }

        void report(String family) {
            System.out.printf(
                    Locale.ROOT,
                    "%s: %d programs (%d contours not recognised), %d refused, %d entries, %d keep the core in place"
                            + " (worst %.3f mm)%n",
                    family,
                    programs,
                    unrecognised,
                    refused,
                    entries,
                    unsafe.size(),
                    unsafe.isEmpty() ? Double.NaN : worstMm);
        }

        void assertSafe(String family) {
            assertTrue(
                    unsafe.isEmpty(),
                    family + ": " + unsafe.size() + " entries keep the core in place, e.g. "
                            + unsafe.subList(0, Math.min(5, unsafe.size())));
        }
    }

    /** The default entries (a helix where it has room), and ramps asked for (the 7M ramps either way). */
    static final List<EntryRule> RULES =
            List.of(EntryRule.DEFAULT, new EntryRule(EntryRule.Kind.RAMP, EntryRule.DEFAULT_ANGLE_DEG, false));

    static PocketTechnology withDiameter(PocketTechnology t, double diameterMm) {
        return new PocketTechnology(
                diameterMm,
                t.cutFraction(),
                t.finishFraction(),
                t.zTopMm(),
                t.zBottomMm(),
                t.maxDepthMm(),
                t.spindleRpm(),
                t.feedMmPerMin(),
                t.finishFeedMmPerMin());
    }

    static List<List<Vec2>> descents(Toolpath p) {
        List<List<Vec2>> out = new ArrayList<>();
        for (ToolpathSection s : p.sections()) {
            out.addAll(EntryCoreTest.descents(s));
        }
        return out;
    }

    /** The thesis's passes, the zigzag strategy and the 7M post of one contour and tool. */
    static void all(String what, PocketProfile profile, PocketTechnology t, Tally offset, Tally zigzag, Tally sevenM)
            throws Exception {
        PocketPlan plan;
        try {
            plan = PassPlanner.plan(profile, t, false);
        } catch (ToolTooLargeException e) {
            plan = null; // the tool does not fit: nothing to enter
        } catch (org.fresa.model.CamInputException e) {
            offset.unrecognised++;
            plan = null; // the thesis's recognition does not take this contour: no passes to enter
        }
        if (plan != null) {
            for (EntryRule rule : RULES) {
                try {
                    offset.check(what + " " + rule.kind(), descents(PocketToolpath.of(plan, true, rule)), t.radiusMm());
                } catch (ToolTooLargeException e) {
                    offset.refusal(what + " " + rule.kind(), e);
                }
            }
            try {
                String nc = new Sinumerik7MPost(Sinumerik7MPost.Mode.CORRECTED, true, EntryRule.DEFAULT).write(plan);
                sevenM.check(what, descents7m(nc), t.radiusMm());
            } catch (ToolTooLargeException e) {
                sevenM.refusal(what, e);
            }
        }
        for (EntryRule rule : RULES) {
            try {
                ZigzagPocket.Plan z = ZigzagPocket.plan(profile.outline(), List.of(), t, 0, true, rule);
                zigzag.check(what + " " + rule.kind(), descents(z.toolpath()), t.radiusMm());
            } catch (ToolTooLargeException e) {
                if (!e.getMessage().contains("does not fit")) {
                    zigzag.refusal(what + " " + rule.kind(), e);
                }
            }
        }
    }

    @Test
    void theThesisContoursGoDownMovingTheCentre() throws Exception {
        Tally offset = new Tally();
        Tally zigzag = new Tally();
        Tally sevenM = new Tally();
        for (String name : THESIS) {
            PocketTechnology own = PocketCoverageTest.tech(name);
            PocketProfile profile = RecognitionTest.sample(name + ".dad");
            for (double d : new double[] {own.toolDiameterMm(), 6, 10}) {
                all(name + " D" + d, profile, withDiameter(own, d), offset, zigzag, sevenM);
            }
        }
        assertAllSafe("thesis contours", offset, zigzag, sevenM);
    }

    @Test
    void randomPocketsWithoutIslandsGoDownMovingTheCentre() throws Exception {
        Random rnd = new Random(7);
        Tally offset = new Tally();
        Tally zigzag = new Tally();
        Tally sevenM = new Tally();
        for (int k = 0; k < 100; k++) {
            List<Contour> p = PocketCleanUpTest.pocket(rnd);
            PocketTechnology t = PocketCleanUpTest.tech(rnd);
            // the thesis's recognition takes its contour clockwise
            PocketProfile profile =
                    PocketProfile.fromContours(List.of(p.get(0).ccw().reversed()));
            for (double d : new double[] {6, 10}) {
                all("pocket " + k + " D" + d, profile, withDiameter(t, d), offset, zigzag, sevenM);
            }
        }
        assertAllSafe("random pockets", offset, zigzag, sevenM);
        assertTrue(offset.programs >= 190, "planned " + offset.programs + ", refused " + offset.refused);
    }

    static void assertAllSafe(String family, Tally offset, Tally zigzag, Tally sevenM) {
        offset.report(family + ", offset passes");
        zigzag.report(family + ", zigzag");
        sevenM.report(family + ", 7m");
        offset.assertSafe(family + ", offset passes");
        zigzag.assertSafe(family + ", zigzag");
        sevenM.assertSafe(family + ", 7m");
    }

    private static final Pattern WORD = Pattern.compile("([GXYZ])\\s*(-?\\d+)");

    /**
     * The descents of a 7M program (micrometres, G90/G91 modal; its arcs lie in the plane, so only
     * G01 blocks go down, each with its Z word), as tool centre positions in mm: a run of feed
     * blocks with Z, none going up.
     */
    static List<List<Vec2>> descents7m(String nc) {
        List<List<Vec2>> out = new ArrayList<>();
        boolean incremental = false;
        boolean feed = false;
        long x = 0;
        long y = 0;
        long z = 0;
        List<Vec2> run = new ArrayList<>();
        for (String line : nc.lines().toList()) {
            Matcher m = WORD.matcher(line);
            long nx = x;
            long ny = y;
            long nz = z;
            boolean moves = false;
            boolean hasZ = false;
            List<String[]> words = new ArrayList<>();
            while (m.find()) {
                words.add(new String[] {m.group(1), m.group(2)});
            }
            for (String[] w : words) {
                if (w[0].equals("G")) {
                    int g = Integer.parseInt(w[1]);
                    if (g == 90 || g == 91) {
                        incremental = g == 91;
                    } else if (g <= 3) {
                        feed = g != 0;
                    }
                }
            }
            if (line.contains("G53") || line.contains("G54")) {
                continue; // machine and work offsets, no tool movement in the pocket
            }
            for (String[] w : words) {
                long v = Long.parseLong(w[1]);
                switch (w[0]) {
                    case "X" -> nx = incremental ? x + v : v;
                    case "Y" -> ny = incremental ? y + v : v;
                    case "Z" -> {
                        nz = incremental ? z + v : v;
                        hasZ = true;
                    }
                    default -> {
                        continue;
                    }
                }
                moves = true;
            }
            if (!moves) {
                continue;
            }
            // a ramp's blocks all say Z, a block too short to descend a micrometre says Z0
            if (feed && hasZ && nz <= z && (nz < z || !run.isEmpty())) {
                if (run.isEmpty()) {
                    run.add(new Vec2(x / 1000.0, y / 1000.0));
                }
                run.add(new Vec2(nx / 1000.0, ny / 1000.0));
            } else if (!run.isEmpty()) {
                out.add(run);
                run = new ArrayList<>();
            }
            x = nx;
            y = ny;
            z = nz;
        }
        if (!run.isEmpty()) {
            out.add(run);
        }
        return out;
    }
}
