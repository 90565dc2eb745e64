package org.fresa.post;

import java.util.List;

/** Lets tests in other packages read the joints of a written program. */
public final class RobotProgramWritersTestAccess {
    private RobotProgramWritersTestAccess() {}

    public static List<double[]> jointsIn(String program) {
        return RobotProgramWritersTest.jointsIn(program);
    }
}
