package org.fresa.job;

import java.nio.file.Files;
import java.nio.file.Path;
import org.fresa.kin.Robots;
import org.fresa.model.Placement;

public class DebugService {
    public static void main(String[] a) throws Exception {
        Path dir = Files.createTempDirectory("dbg");
        var req = new RobotTrajectoryService.Request(RobotTrajectoryServiceTest.cube(), Robots.byName(a[0]).orElseThrow(),
                new Placement(Double.parseDouble(a[1]), Double.parseDouble(a[2]), Double.parseDouble(a[3]), 0, 0, 0),
                new Placement(0, 10, 0, 0, 0, 0));
        long t0 = System.nanoTime();
        if (a.length > 4) {
            req = new RobotTrajectoryService.Request(req.toolpath(), req.robot(), req.robotTable(), req.tablePiece(), 0.01,
                    java.util.List.of("csv"), req.options());
        }
        TaskOutcome o = RobotTrajectoryService.run(req, new OutputFolder(dir), ProgressMonitor.NONE);
        System.out.println((System.nanoTime() - t0) / 1e6 + " ms " + o.summary());
        System.out.println(dir);
    }
}
