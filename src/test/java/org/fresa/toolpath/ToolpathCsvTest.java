package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.util.List;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;
import org.junit.jupiter.api.Test;

class ToolpathCsvTest {

    private static Toolpath quarterTurns() {
        List<Move> moves = List.of(
                new Move.Rapid(new Vec3(10, 0, 1)),
                new Move.Linear(new Vec3(10, 0, -0.1), 300),
                new Move.Circular(
                        new Vec3(0, 10, -0.1), Vec3.ZERO.plus(new Vec3(0, 0, -0.1)), Vec3.UNIT_Z, true, 0, 600),
                new Move.Circular(new Vec3(10, 0, -0.1), new Vec3(0, 0, -0.1), Vec3.UNIT_Z.negated(), true, 0, 600));
        return new Toolpath(
                List.of(new ToolpathSection("WS, \"one\"", Vec3.UNIT_Z, 6, 1, 1000, new Vec3(0, 0, 50), moves)));
    }

    @Test
    void theFileHasTheSpecifiedHeaderAndOneRowPerPointWithArcsAtTheChordTolerance() {
        String text = ToolpathCsv.toText(quarterTurns(), 0.01);
        List<String> lines = text.lines().toList();
        assertEquals("index,workingstep,move,x,y,z,i,j,k,feed", lines.get(0));
        assertEquals("0,\"WS, \"\"one\"\"\",rapid,0,0,50,0,0,1,0", lines.get(1));
        assertEquals("2,\"WS, \"\"one\"\"\",feed,10,0,-0.1,0,0,1,300", lines.get(3));
        // a quarter turn of radius 10 within 0.01 mm: steps of at most 2 acos(0.999) = 0.0894 rad, so 18
        long ccw = lines.stream().filter(l -> l.contains(",arc-ccw,")).count();
        assertEquals(18, ccw);
        // counter-clockwise about -Z is a G02 seen from +Z: back the short way from 90 to 0 degrees
        long cw = lines.stream().filter(l -> l.contains(",arc-cw,")).count();
        assertEquals(18, cw);
    }

    @Test
    void arcPointsLieOnTheArcAndEndExactlyAtItsEnd() throws Exception {
        List<ToolpathCsv.Row> rows = ToolpathCsv.read(new StringReader(ToolpathCsv.toText(quarterTurns(), 0.01)), "t");
        for (ToolpathCsv.Row r : rows) {
            if (r.move().startsWith("arc")) {
                assertEquals(10, r.point().xy().norm(), 1e-9);
                assertEquals(-0.1, r.point().z(), 0);
            }
        }
        ToolpathCsv.Row last = rows.get(rows.size() - 1);
        assertEquals(new Vec3(10, 0, -0.1), last.point());
        assertTrue(rows.stream().allMatch(r -> r.workingstep().equals("WS, \"one\"")));
        assertEquals(rows.size() - 1, last.index());
    }

    /** A dwell is a row of its own (feed column: seconds); spindle events have none. */
    @Test
    void aDwellIsADwellRowWithItsSecondsAndSpindleEventsHaveNoRow() throws Exception {
        Vec3 bottom = new Vec3(5, 5, -12);
        List<Move> moves = List.of(
                new Move.Rapid(new Vec3(5, 5, 2)),
                new Move.Linear(bottom, 100),
                new Move.Dwell(bottom, 1.5),
                new Move.SpindleStop(bottom),
                new Move.Linear(new Vec3(5, 5, 2), 100),
                new Move.SpindleStart(new Vec3(5, 5, 2), 900, true),
                new Move.Rapid(new Vec3(5, 5, 20)));
        Toolpath p =
                new Toolpath(List.of(new ToolpathSection("bore", Vec3.UNIT_Z, 10, 2, 900, new Vec3(5, 5, 20), moves)));
        List<String> lines = ToolpathCsv.toText(p, 0.01).lines().toList();
        assertEquals(
                List.of(
                        "index,workingstep,move,x,y,z,i,j,k,feed",
                        "0,bore,rapid,5,5,20,0,0,1,0",
                        "1,bore,rapid,5,5,2,0,0,1,0",
                        "2,bore,feed,5,5,-12,0,0,1,100",
                        "3,bore,dwell,5,5,-12,0,0,1,1.5",
                        "4,bore,feed,5,5,2,0,0,1,100",
                        "5,bore,rapid,5,5,20,0,0,1,0"),
                lines);
        List<ToolpathCsv.Row> rows = ToolpathCsv.read(new StringReader(String.join("\n", lines)), "t");
        assertEquals("dwell", rows.get(3).move());
        assertEquals(1.5, rows.get(3).feedMmPerMin());
    }
}
