package org.fresa.kin;

public class DebugMain {
    public static void main(String[] a) throws Exception {
        Robot robot = Robots.byName(a[1]).orElseThrow();
        IkOptions ik = a[2].equals("T") ? IkOptions.THESIS : IkOptions.DEFAULT;
        TrajectorySolver.Result r = new TrajectorySolver(robot, TrajectorySolver.Options.DEFAULT.withIk(ik))
                .solve(AppendixCTest.targets(a[0], robot.controlsFullOrientation()), null);
        for (TrajectoryPoint p : r.points()) {
            StringBuilder sb = new StringBuilder(p.label() + " " + p.status() + " ins=" + p.inserted() + " phi=" + p.freeRotationDeg());
            for (double v : p.q()) sb.append(String.format(" %8.3f", v));
            System.out.println(sb);
        }
        System.out.println(r.notes());
    }
}
