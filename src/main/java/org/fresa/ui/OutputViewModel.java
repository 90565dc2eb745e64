package org.fresa.ui;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;
import org.fresa.io.OutputFolder;
import org.fresa.job.RobotTrajectoryService;
import org.fresa.job.TaskOutcome;

/**
 * The Output tab's state without Swing: which formats are checked, which one is previewed, and
 * the writing of the last trajectory through {@link RobotTrajectoryService#write}.
 */
final class OutputViewModel {

    /** The formats in the order shown, with what each writes. */
    static final List<String> FORMATS = List.of("csv", "xml", "rapid", "krl", "png");

    /** Words coloured in a program preview: motion instructions and declarations. */
    static final Pattern KEYWORDS = Pattern.compile("\\b(MoveAbsJ|MoveL|MoveJ|PTP|LIN|MODULE|ENDMODULE|PROC|ENDPROC|"
            + "DEF|END|PERS|CONST|VAR|tooldata|wobjdata|robtarget|jointtarget|DECL|BAS|Activity|JointValue)\\b");

    private final Set<String> checked = new LinkedHashSet<>(List.of("csv", "xml", "png"));
    private String previewed = "rapid";

    /** What a format writes: the file its preview shows, and its line in the list of formats. */
    private record Written(String previewFile, String description) {}

    private static final Map<String, Written> WRITTEN = Map.of(
            "csv", new Written("trajectory.csv", "csv: trajectory.csv (joint values per point)"),
            "xml", new Written("program.xml", "xml: program.xml (offline-programming XML)"),
            "rapid", new Written("program.mod", "rapid: program.mod (ABB RAPID)"),
            "krl", new Written("program.src", "krl: program.src (KUKA KRL)"),
            "png", new Written("joints.png", "png: joints.png and error.png (charts)"));

    static String describe(String format) {
        Written w = WRITTEN.get(format);
        return w == null ? format : w.description();
    }

    /** The file a format's preview shows. */
    static String fileOf(String format) {
        Written w = WRITTEN.get(format);
        if (w == null) {
            throw new IllegalArgumentException(format);
        }
        return w.previewFile();
    }

    boolean isChecked(String f) {
        return checked.contains(f);
    }

    void setChecked(String f, boolean on) {
        if (!FORMATS.contains(f)) {
            throw new IllegalArgumentException("unknown format " + f);
        }
        if (on) {
            checked.add(f);
        } else {
            checked.remove(f);
        }
    }

    /** The checked formats in the shown order. */
    List<String> checkedFormats() {
        List<String> out = new ArrayList<>();
        for (String f : FORMATS) {
            if (checked.contains(f)) {
                out.add(f);
            }
        }
        return out;
    }

    void setCheckedFormats(List<String> fs) {
        checked.clear();
        for (String f : fs) {
            if (FORMATS.contains(f)) {
                checked.add(f);
            }
        }
    }

    String previewed() {
        return previewed;
    }

    void preview(String f) {
        if (!FORMATS.contains(f)) {
            throw new IllegalArgumentException("unknown format " + f);
        }
        previewed = f;
    }

    /** Why saving is not possible now, or empty when it is. */
    String saveProblem(boolean haveResult) {
        if (!haveResult) {
            return "Nothing to save yet: compute a trajectory in the Position tab first.";
        }
        if (checked.isEmpty()) {
            return "Check at least one format.";
        }
        return "";
    }

    /** Writes the given formats of a run into a folder (plus summary.json). */
    static TaskOutcome write(RobotRunModel.Run run, List<String> formats, OutputFolder out) throws IOException {
        RobotTrajectoryService.Request r = run.solved().request();
        RobotTrajectoryService.Request req = new RobotTrajectoryService.Request(
                r.toolpath(),
                r.robot(),
                r.robotTable(),
                r.tablePiece(),
                r.chordToleranceMm(),
                formats,
                r.options(),
                r.tcpByLabel(),
                r.checkLimits());
        TaskOutcome written = RobotTrajectoryService.write(
                new RobotTrajectoryService.Solved(
                        req, run.solved().targets(), run.solved().result()),
                run.programName(),
                out);
        // what fresa run says: the planning's warnings with what writing says, in one place
        return org.fresa.job.RobotService.outcome(run.planning(), written, written.files());
    }

    /**
     * Writes one format into a scratch folder and returns the file to preview (text, or the
     * joints chart for png). The scratch folder is the caller's to delete.
     */
    static Path previewFile(RobotRunModel.Run run, String format, Path scratch) throws IOException {
        OutputFolder out = new OutputFolder(scratch);
        write(run, List.of(format), out);
        if (org.fresa.robot.RobotPrograms.FORMATS.contains(format)
                && refusal(run).isPresent()) {
            // refused programs are not saved; the preview shows the program so that its failing motion can be marked
            org.fresa.robot.RobotPrograms.write(
                    program(run), run.solved().request().robot(), List.of(format), out);
        }
        Path f = scratch.resolve(fileOf(format));
        if (!Files.exists(f)) {
            throw new IOException("the " + format + " writer wrote no " + fileOf(format));
        }
        return f;
    }

    /** The robot program of a run, as the writers and Save take it (tool frames, dwells). */
    static org.fresa.post.RobotProgram program(RobotRunModel.Run run) {
        return RobotTrajectoryService.program(run.solved(), run.programName());
    }

    /** The program check's first failure of a run's robot program (as Save would check it), or empty. */
    static java.util.Optional<org.fresa.check.Failure> refusal(RobotRunModel.Run run) {
        return RobotTrajectoryService.check(
                run.solved(), program(run), run.solved().request().checkLimits());
    }

    /**
     * The line (from 1) of a program text that holds the motion of the trajectory row: RAPID and
     * KRL end each motion's line with its index, program.xml carries it as {@code Index}; 0 when
     * none does.
     */
    static int lineOfMotion(String text, int index) {
        String[] lines = text.split("\n", -1);
        for (int i = 0; i < lines.length; i++) {
            String l = lines[i];
            if (l.endsWith("! " + index) || l.endsWith("; " + index) || l.contains("Index=\"" + index + "\"")) {
                return i + 1;
            }
        }
        return 0;
    }

    /** Start and end offsets of the keywords in a program text, for colouring. */
    static List<int[]> keywordSpans(String text) {
        List<int[]> out = new ArrayList<>();
        var m = KEYWORDS.matcher(text);
        while (m.find()) {
            out.add(new int[] {m.start(), m.end()});
        }
        return out;
    }
}
