package org.fresa.app.cli;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Map;
import org.fresa.cell.RobotTools;
import org.fresa.job.IkService;
import org.fresa.job.ProgressMonitor;
import org.fresa.job.TaskOutcome;
import org.fresa.kin.IkOptions;
import org.fresa.model.CamInputException;
import org.fresa.setting.SettingRanges;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code fresa ik TARGETS.csv --robot NAME|FILE --out DIR [ik options]}. */
@Command(
        name = "ik",
        description = "Inverse kinematics of any list of tool poses (x,y,z,roll,pitch,yaw[,q1..qN] per row).")
final class IkCommand extends FolderCommand {

    @Parameters(
            index = "0",
            paramLabel = "TARGETS.csv",
            description = "header x,y,z,roll,pitch,yaw[,q1,...,qN]; mm and deg in the robot base frame, "
                    + "R = Rz(roll)*Ry(pitch)*Rx(yaw); optional seed joints")
    Path targets;

    @Mixin
    RobotOptions robot = new RobotOptions();

    @Option(
            names = "--tolerance-mm",
            paramLabel = "T",
            defaultValue = "1e-7",
            description = "position tolerance (mm); the orientation's is T/100 rad; default ${DEFAULT-VALUE}")
    double toleranceMm;

    @Option(
            names = "--method",
            paramLabel = "default|thesis-dls",
            description = "Levenberg-Marquardt with the closed form where the robot has one (default), or the"
                    + " thesis's damped least squares")
    IkOptions.Method method = IkOptions.DEFAULT.method();

    @Option(
            names = "--configuration",
            paramLabel = "K=V[,K=V]",
            description = "keep only solutions in this arm configuration: cf1, cf4, cf6, cfx (ABB confdata), S, T"
                    + " (KUKA Status and Turn)")
    String configuration;

    @Option(names = "--all", description = "every solution branch of each pose (column branch)")
    boolean all;

    @Option(
            names = "--spindle",
            paramLabel = "X,Y,Z[,RX,RY,RZ]",
            description = "spindle nose in the flange frame (mm, deg); default: the robot file's tool frame, else"
                    + " the flange")
    String spindle;

    @Option(
            names = "--tool-length",
            paramLabel = "MM",
            description = "tool length from the spindle nose to the tip; the TCP is spindle * Tz(tool length)")
    Double toolLength;

    @Override
    TaskOutcome work(ProgressMonitor progress) throws CamInputException, IOException {
        double tol = SettingRanges.Robot.IK_TOLERANCE.check(toleranceMm);
        Map<String, Integer> conf = configuration == null ? Map.of() : IkService.parseConfiguration(configuration);
        RobotTools.Choice tool = RobotOptions.tool(spindle, toolLength);
        IkService.Settings s = new IkService.Settings(targets, robot.robot, tool, method, tol, conf, all);
        return CliSupport.intoFolder(out, folder -> IkService.run(s, folder, progress));
    }
}
