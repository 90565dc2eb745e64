package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.DoubleFunction;
import org.fresa.io.OutputFolder;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.TaskOutcome;
import org.fresa.job.ToolpathService;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;
import org.fresa.post.MillingPost;
import org.fresa.post.Rs274;
import org.junit.jupiter.api.Assumptions;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.prep.PreparedGeometry;
import org.locationtech.jts.geom.prep.PreparedGeometryFactory;

/**
 * The acceptance checks of a milled feature (JTS): the tool's cross-section along its moves at
 * every 0.5 mm of height stays within the feature's cross-section there by 0.01 mm; its floor is
 * cleared where the tool's disc reaches; the program of the part passes the program check and
 * LinuxCNC's interpreter.
 */
final class FeatureVolumeCheck {

    /** Heights between checks of the cross-section (mm). */
    static final double SLICE_MM = 0.5;

    private FeatureVolumeCheck() {}

    /** The lowest height the section's moves reach. */
    static double lowest(ToolpathSection sec) {
        return sec.moves().stream().mapToDouble(m -> m.end().z()).min().orElseThrow();
    }

    /** The heights checked: from the top (z 0) down every {@link #SLICE_MM} to the section's lowest point. */
    static double[] slices(ToolpathSection sec) {
        double lowest = lowest(sec);
        java.util.List<Double> z = new java.util.ArrayList<>();
        for (double at = 0; at >= lowest - 1e-9; at -= SLICE_MM) {
            z.add(Math.max(at, lowest));
        }
        return z.stream().mapToDouble(Double::doubleValue).toArray();
    }

    /**
     * The tool's shadow outside the feature's cross-section grown by 0.01 mm (mm2), at the worst
     * height checked.
     *
     * @param featureAt the feature's cross-section at a height (with the outside of the block where
     *     the tool may run in the air)
     */
    static double outside(ToolpathSection sec, SlotProfilesTest.Shape tool, DoubleFunction<Geometry> featureAt) {
        double out = 0;
        for (double z : slices(sec)) {
            out = Math.max(out, outsideAt(sec, tool, z, featureAt.apply(z)));
        }
        return out;
    }

    /** The tool's shadow at height z outside the feature's cross-section grown by 0.01 mm (mm2). */
    static double outsideAt(ToolpathSection sec, SlotProfilesTest.Shape tool, double z, Geometry feature) {
        return outsideGrown(sec, tool, z, feature.buffer(0.01, 64));
    }

    /** {@link SlotProfilesTest#outside}, the allowed region prepared once for the many moves of a section. */
    private static double outsideGrown(ToolpathSection sec, SlotProfilesTest.Shape tool, double z, Geometry allowed) {
        PreparedGeometry prepared = PreparedGeometryFactory.prepare(allowed);
        double area = 0;
        for (Geometry g : SlotProfilesTest.slice(sec, tool, z)) {
            if (!prepared.covers(g)) {
                area += g.difference(allowed).getArea();
            }
        }
        return area;
    }

    /** At every height checked, the tool's shadow stays within the feature's cross-section by 0.01 mm. */
    static void assertInside(ToolpathSection sec, SlotProfilesTest.Shape tool, DoubleFunction<Geometry> featureAt) {
        Geometry last = null;
        Geometry grown = null;
        for (double z : slices(sec)) {
            Geometry feature = featureAt.apply(z);
            if (feature != last) {
                // a feature the same at every height is grown once
                last = feature;
                grown = feature.buffer(0.01, 64);
            }
            double out = outsideGrown(sec, tool, z, grown);
            assertTrue(out < 1e-6, sec.label() + " leaves its feature at z " + z + " by " + out + " mm2");
        }
    }

    /**
     * The floor left uncut (mm2) by the tool's disc along the moves at the section's lowest
     * height; with residue, less what a cutter of this radius cannot reach in the floor's corners.
     */
    static double uncut(ToolpathSection sec, double radius, Geometry floor, boolean residue) {
        Geometry swept = Swept.sweep(sec, radius, lowest(sec));
        return residue
                ? Swept.uncutBeyondResidue(floor, swept, radius)
                : floor.difference(swept).getArea();
    }

    /** The floor is cleared where the tool's disc reaches, but for 0.01 mm2. */
    static void assertFloorCleared(ToolpathSection sec, double radius, Geometry floor) {
        double left = uncut(sec, radius, floor, true);
        assertTrue(left < 1e-2, sec.label() + " leaves " + left + " mm2 of its floor");
    }

    /** The section's lowest move is at the floor expected. */
    static void assertFloor(ToolpathSection sec, double floorZ, double within) {
        double lowest = Double.POSITIVE_INFINITY;
        for (Move m : sec.moves()) {
            lowest = Math.min(lowest, m.end().z());
        }
        assertEquals(floorZ, lowest, within, sec.label() + ": the floor");
    }

    /**
     * The part's program for LinuxCNC is made (the program check lets it through) and LinuxCNC's
     * interpreter accepts it (when it is installed).
     */
    static void assertProgramAccepted(Path part, Path dir) throws Exception {
        Path out = dir.resolve("out");
        TaskOutcome o = ToolpathService.run(part, MillingPost.LINUXCNC, new OutputFolder(out), ProgressMonitor.NONE);
        assertEquals(0, o.exitStatus(), o.problems().toString());
        Path program = out.resolve("program.ngc");
        assertTrue(Files.exists(program), "the program check let the program through");
        Assumptions.assumeTrue(Rs274.available(), Rs274.whyNot());
        Rs274.Result r = Rs274.run(program, 20);
        assertEquals(0, r.exitStatus(), () -> "rs274 rejected the program: " + Rs274.log(r));
    }

    /** {@link #assertProgramAccepted(Path, Path)} for a part given as text. */
    static void assertProgramAccepted(String part, String name, Path dir) throws Exception {
        Path file = dir.resolve(name);
        Files.writeString(file, part);
        assertProgramAccepted(file, dir);
    }

    /** The planned section of this workingstep, or a failure naming what the planner said. */
    static ToolpathSection section(ToolpathPlanner.Plan plan, String label) {
        return plan.toolpath().sections().stream()
                .filter(x -> x.label().equals(label))
                .findFirst()
                .orElseThrow(() -> new AssertionError(label + " not planned: " + plan.problems()));
    }
}
