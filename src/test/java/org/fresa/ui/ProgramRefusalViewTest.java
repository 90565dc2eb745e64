package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Optional;
import javax.swing.JTextArea;
import javax.swing.text.Highlighter;
import org.assertj.swing.edt.GuiActionRunner;
import org.fresa.chart.PlotScene;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.pocket.EntryRule;
import org.fresa.pocket.MillingDirection;
import org.fresa.pocket.PocketStrategy;
import org.junit.jupiter.api.Test;

/** The Pocket and Output tabs' side of the program check: the failing block found and marked. */
class ProgramRefusalViewTest {

    private static final PocketSettings CAVITY03 = new PocketSettings(
            Path.of("samples/pocket/cavity03.dad"),
            6,
            0.73,
            0.22,
            30,
            27,
            5,
            2750,
            280,
            90,
            org.fresa.post.PocketPost.SINUMERIK_7M_COMPAT,
            MillingDirection.CLIMB,
            EntryRule.Kind.AUTO,
            EntryRule.DEFAULT_ANGLE_DEG,
            false,
            Optional.empty(),
            PocketStrategy.DEFAULT);

    @Test
    void theThesisProgramOfCavity03PassesTheCheck() {
        PocketViewModel m = new PocketViewModel();
        m.setSettings(CAVITY03);
        m.compute();
        assertTrue(m.result().orElseThrow().refusal().isEmpty());
    }

    @Test
    void aProgramCuttingWithTheSpindleStoppedIsRefusedAtItsBlock() {
        String nc = "N05 %\nN10 G00 G90 X 0 Y 0 Z 5000\nN15 G01 G91 Z-8000F 280\nN20 M30\n";
        PocketViewModel.Result r = PocketViewModel.Result.checked(PlotScene.empty("x"), "", nc, CAVITY03);
        assertEquals(3, r.refusal().orElseThrow().line());
        assertEquals("spindle", r.refusal().get().rule().name());
        // Swing components are made and read on the event thread: AssertJ Swing's check of that
        // stays installed after a GUI test has run in the same JVM
        JTextArea text = GuiActionRunner.execute(() -> new JTextArea(nc));
        assertTrue(GuiActionRunner.execute(() -> ProgramHighlight.line(text, 3)));
        Highlighter.Highlight[] marked =
                GuiActionRunner.execute(() -> text.getHighlighter().getHighlights());
        assertEquals(1, marked.length);
        assertEquals(nc.indexOf("N15"), marked[0].getStartOffset());
        assertFalse(GuiActionRunner.execute(() -> ProgramHighlight.line(text, 9)));
    }

    @Test
    void theMotionOfARobotProgramIsFoundByItsIndex() {
        String rapid = "    MoveAbsJ [[0,0,0,0,0,0],[9E+09]],v,fine,tFresa; ! 0\n    MoveL [[1,2,3]] ! j=[1] ! 17\n";
        assertEquals(2, OutputViewModel.lineOfMotion(rapid, 17));
        assertEquals(1, OutputViewModel.lineOfMotion("<Activity Index=\"4\" Workingstep=\"w\">\n", 4));
        assertEquals(0, OutputViewModel.lineOfMotion(rapid, 5));
    }
}
