package org.fresa.toolpath;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.geom.Tolerance;
import org.fresa.stepnc.StepNcReader;
import org.junit.jupiter.api.Test;

/**
 * A planar face's face_boundary (the face bounded inside its removal rectangle) and an open
 * pocket's wall_boundary (walls of a shape of their own) are not read: milling without them would
 * cut past what the file keeps, so the workingstep is refused naming them. No sample or corpus
 * file gives either.
 */
class UnreadBoundariesTest {

    static String refusal(String text, String ws) throws Exception {
        ToolpathPlanner.Plan p =
                ToolpathPlanner.plan(StepNcReader.read(new StringReader(text), "b.stp"), Tolerance.DEFAULT);
        assertTrue(
                p.toolpath().sections().stream().noneMatch(s -> s.label().equals(ws)),
                p.problems().toString());
        return p.problems().stream()
                .filter(x -> x.startsWith("workingstep '" + ws + "' (#"))
                .findFirst()
                .orElseThrow(() -> new AssertionError(ws + " not refused: " + p.problems()));
    }

    @Test
    void aFaceBoundaryIsNotMilledPast() throws Exception {
        String face = "#16= PLANAR_FACE('PLANAR FACE1',#4,(#19),#77,#63,#24,#25,$,());";
        String text = Files.readString(Path.of("samples/stepnc/iso14649-11-example1.stp"));
        assertTrue(text.contains(face));
        text = text.replace(face, face.replace("#25,$,", "#25,#900,") + "\n#900= CIRCULAR_CLOSED_PROFILE($,50.000);");
        assertTrue(refusal(text, "WS FINISH PLANAR FACE1")
                .contains("within a face_boundary (CIRCULAR_CLOSED_PROFILE) are not supported yet"));
    }

    @Test
    void anOpenPocketsWallBoundaryIsNotMilledUpright() throws Exception {
        String pocket = "#19= OPEN_POCKET('OPEN POCKET',#4,(#34),#85,#88,(),$,#257,$,$,#235,$);";
        String text = Files.readString(Path.of("src/test/resources/stepnc/steps-outside-profiles.stp"));
        assertTrue(text.contains(pocket));
        text = text.replace(
                pocket, pocket.replace("#235,$);", "#235,#901);") + "\n#901= VEE_PROFILE($,$,60.000,60.000);");
        assertTrue(refusal(text, "WS OPEN POCKET").contains("with a wall_boundary (VEE_PROFILE)"));
    }
}
