package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.fresa.cell.RobotTools;
import org.fresa.cell.TablePlacing;
import org.fresa.io.OutputFolder;
import org.fresa.model.Placement;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code --place auto} on example 2: at the default placement the Tricept reaches none of its
 * targets; the search finds a placement from which the whole trajectory is solved, and a robot
 * that cannot reach some workingsteps from anywhere is told which, with no trajectory.
 */
class PlacementSearchAcceptanceTest {

    @TempDir
    Path dir;

    TaskOutcome run(String robot) throws Exception {
        return RobotService.run(
                new RobotService.Settings(
                        Path.of("samples/stepnc/example2.stp"),
                        robot,
                        Placement.ORIGIN,
                        new Placement(0, 10, 0, 0, 0, 0),
                        List.of("csv"),
                        org.fresa.toolpath.PlanningChoices.DEFAULT,
                        RobotTools.Choice.NONE,
                        TablePlacing.AUTO),
                new OutputFolder(dir),
                ProgressMonitor.NONE);
    }

    @Test
    void example2IsFullyReachableOnTheTriceptFromThePlacementFound() throws Exception {
        TaskOutcome o = run("tricept806");
        assertEquals(0, o.exitStatus(), o.problems()::toString);
        assertEquals(0, o.summary().get("unreachable"));
        Map<?, ?> p = (Map<?, ?>) o.summary().get("placement_search");
        assertEquals(true, p.get("found"));
        assertEquals(p.get("targets"), p.get("reached"));
        assertTrue(((Number) p.get("min_joint_margin")).doubleValue() > 0.05, p::toString);
        assertTrue(Files.readString(dir.resolve("summary.json")).contains("\"placement_search\""));
        // every row of the trajectory solved
        for (String row : Files.readAllLines(dir.resolve("trajectory.csv")).subList(1, 10)) {
            assertTrue(!row.endsWith(",unreachable"), row);
        }
    }

    @Test
    void theSidesOfExample2AreOutOfReachOfTheScaraFromEveryPlacementAndNamed() throws Exception {
        TaskOutcome o = run("adept-one");
        assertEquals(1, o.exitStatus());
        Map<?, ?> p = (Map<?, ?>) o.summary().get("placement_search");
        assertEquals(false, p.get("found"));
        List<?> nowhere = (List<?>) p.get("out_of_reach_everywhere");
        assertTrue(!nowhere.isEmpty());
        // each workingstep by its id and entity: example 2's ids repeat
        assertEquals(nowhere.size(), nowhere.stream().distinct().count());
        assertTrue(nowhere.stream().allMatch(n -> n.toString().matches(".+ \\(#\\d+\\)")), nowhere::toString);
        String problem = String.join("\n", o.problems());
        for (Object n : nowhere) {
            assertTrue(problem.contains(n.toString()), problem);
        }
        // never a partial placement: no trajectory
        assertTrue(!Files.exists(dir.resolve("trajectory.csv")));
    }
}
