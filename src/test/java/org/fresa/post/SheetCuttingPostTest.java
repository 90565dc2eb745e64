package org.fresa.post;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.StringWriter;
import java.util.List;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;
import org.junit.jupiter.api.Test;

/** The sheet-cutting post and the moves that do not travel. */
class SheetCuttingPostTest {

    static Toolpath cut(Move extra) {
        List<Move> moves = List.of(
                new Move.Rapid(new Vec3(10, 0, 0)),
                new Move.Linear(new Vec3(20, 0, 0), 1000),
                extra,
                new Move.Linear(new Vec3(20, 10, 0), 1000));
        return new Toolpath(List.of(new ToolpathSection("c1", Vec3.UNIT_Z, 2, 1, 0, Vec3.ZERO, moves)));
    }

    static String program(Toolpath p, CuttingPost d) throws Exception {
        StringWriter w = new StringWriter();
        SheetCuttingPost.write(p, "t", new SheetCuttingPost.Job("laser", 0, List.of(0), 2), d, w);
        return w.toString();
    }

    /** A dwell in a cut is the dialect's own dwell block, between the two feeds, the jet on. */
    @Test
    void aDwellInACutIsWrittenWithTheDialectsDwellWord() throws Exception {
        String text = program(cut(new Move.Dwell(new Vec3(20, 0, 0), 1.5)), CuttingPost.LINUXCNC);
        List<String> lines =
                text.lines().map(l -> l.replaceFirst("^N\\d+ ", "")).toList();
        int at = lines.indexOf("G4 P1.5");
        assertEquals("G1 X20 Y10", lines.get(at + 1).replaceFirst(" F.*", ""), text);
        assertEquals(
                List.of("M64 P0"),
                lines.stream().filter(l -> l.startsWith("M64")).toList());
        String fanuc = program(cut(new Move.Dwell(new Vec3(20, 0, 0), 1.5)), CuttingPost.FANUC);
        assertEquals(1, fanuc.lines().filter(l -> l.endsWith("G04 X1.500")).count(), fanuc);
        // iso as the milling iso post: X in seconds, never P (milliseconds on Fanuc-like controls)
        String iso = program(cut(new Move.Dwell(new Vec3(20, 0, 0), 2)), CuttingPost.ISO);
        assertEquals(1, iso.lines().filter(l -> l.endsWith("G04 X2.000")).count(), iso);
        assertEquals(0, iso.lines().filter(l -> l.contains("G04 P")).count(), iso);
    }

    @Test
    void aSheetCuttingHeadHasNoSpindleToStop() {
        assertThrows(
                IllegalArgumentException.class,
                () -> program(cut(new Move.SpindleStop(new Vec3(20, 0, 0))), CuttingPost.LINUXCNC));
    }
}
