package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fresa.io.OutputFolder;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.RobotTrajectoryService;
import org.fresa.model.Placement;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class OutputViewModelTest {

    @TempDir
    Path dir;

    @Test
    void formatsAreCheckedInTheShownOrder() {
        OutputViewModel vm = new OutputViewModel();
        assertEquals(List.of("csv", "xml", "png"), vm.checkedFormats());
        vm.setChecked("krl", true);
        vm.setChecked("csv", false);
        vm.setChecked("rapid", true);
        assertEquals(List.of("xml", "rapid", "krl", "png"), vm.checkedFormats());
        assertThrows(IllegalArgumentException.class, () -> vm.setChecked("gcode", true));
    }

    @Test
    void savingNeedsAResultAndAFormat() {
        OutputViewModel vm = new OutputViewModel();
        assertTrue(vm.saveProblem(false).contains("Position tab"));
        vm.setCheckedFormats(List.of());
        assertEquals("Check at least one format.", vm.saveProblem(true));
    }

    @Test
    void motionKeywordsAreFoundForColouring() {
        String text = "  MoveAbsJ j1, v100;\n  MoveL p1, v50;\nPTP {A1 0}\nLIN {X 1}\nMoveLX";
        List<String> words = OutputViewModel.keywordSpans(text).stream()
                .map(s -> text.substring(s[0], s[1]))
                .toList();
        assertEquals(List.of("MoveAbsJ", "MoveL", "PTP", "LIN"), words);
    }

    @Test
    void theChosenFormatsOfARunAreWrittenAndPreviewed() throws Exception {
        RobotTrajectoryService.Solved s = PositionViewModel.compute(
                Path.of("samples/stepnc/iso14649-11-example1.stp"),
                "irb140",
                new Placement(400, -200, 500, 0, 0, 0),
                new Placement(0, 10, 0, 0, 0, 0),
                List.of("csv"),
                ProgressMonitor.NONE);
        RobotRunModel.Run run = new RobotRunModel.Run(s, "example1");
        RobotRunModel shared = new RobotRunModel();
        Object[] heard = new Object[1];
        shared.addListener(() -> heard[0] = shared.last().orElse(null));
        shared.set(run);
        assertEquals(run, heard[0]);
        shared.clear();
        assertEquals(null, heard[0]);
        shared.set(run);
        OutputViewModel.write(run, List.of("rapid", "krl"), new OutputFolder(dir.resolve("out")));
        assertTrue(Files.exists(dir.resolve("out/program.mod")));
        assertTrue(Files.exists(dir.resolve("out/program.src")));
        assertTrue(Files.notExists(dir.resolve("out/trajectory.csv")));
        Path rapid = OutputViewModel.previewFile(run, "rapid", dir.resolve("scratch"));
        String text = Files.readString(rapid);
        assertTrue(text.contains("MODULE") && text.contains("MoveL"), text.substring(0, Math.min(400, text.length())));
        assertTrue(!OutputViewModel.keywordSpans(text).isEmpty());
    }

    @Test
    void theProgramTheTabChecksAndShowsIsTheOneSaveWrites() throws Exception {
        RobotTrajectoryService.Solved s = PositionViewModel.compute(
                Path.of("samples/stepnc/iso14649-11-example1.stp"),
                "irb140",
                new Placement(400, -200, 500, 0, 0, 0),
                new Placement(0, 10, 0, 0, 0, 0),
                List.of("csv"),
                ProgressMonitor.NONE);
        RobotRunModel.Run run = new RobotRunModel.Run(s, "example1");
        OutputViewModel.write(run, List.of("rapid", "krl", "xml"), new OutputFolder(dir.resolve("saved")));
        org.fresa.robot.RobotPrograms.write(
                OutputViewModel.program(run),
                s.request().robot(),
                List.of("rapid", "krl", "xml"),
                new OutputFolder(dir.resolve("shown")));
        for (String f : List.of("program.mod", "program.src", "program.xml")) {
            assertEquals(
                    Files.readString(dir.resolve("saved").resolve(f)),
                    Files.readString(dir.resolve("shown").resolve(f)),
                    f);
        }
        assertEquals(
                OutputViewModel.refusal(run),
                org.fresa.job.ProgramChecks.robot(
                        RobotTrajectoryService.program(s, "example1"),
                        s.request().toolpath(),
                        s.request().checkLimits()));
    }
}
