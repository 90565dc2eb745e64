package org.fresa.job;

import java.nio.file.Path;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.geom.Vec2;
import org.fresa.model.Placement;

/**
 * The settings of each module, as they appear in a job file (schemas/job.xsd) and in the tabs.
 * Paths are absolute once a job is read; they are written relative to the job file.
 */
public final class JobSettings {
    private JobSettings() {
    }

    /** STEP-NC input and the machine-tool post used by {@code toolpath}. */
    public record StepNcSettings(Path file, String post) {
        public StepNcSettings {
            Objects.requireNonNull(file, "file");
            Objects.requireNonNull(post, "post");
        }
    }

    /**
     * The robot cell.
     *
     * @param robot a built-in robot name ({@code irb140}) or a robot file path
     * @param robotTable the table origin in the robot base frame
     * @param tablePiece the workpiece origin in the table frame
     * @param formats output formats, e.g. csv, xml, rapid, krl, png
     */
    public record RobotSettings(String robot, Placement robotTable, Placement tablePiece, List<String> formats) {
        public static final List<String> DEFAULT_FORMATS = List.of("csv", "xml", "png");

        public RobotSettings {
            Objects.requireNonNull(robot, "robot");
            Objects.requireNonNull(robotTable, "robotTable");
            Objects.requireNonNull(tablePiece, "tablePiece");
            formats = List.copyOf(formats);
        }
    }

    /** Pocket milling technology (the 1988 thesis's data, samples/pocket/jobs.csv). */
    public record PocketSettings(Path contour, double toolDiameterMm, double cutFraction, double finishFraction,
            double zTopMm, double zBottomMm, double maxDepthPerPassMm, double spindleRpm, double feedMmPerMin,
            double finishFeedMmPerMin, String post) {
        public PocketSettings {
            Objects.requireNonNull(contour, "contour");
            Objects.requireNonNull(post, "post");
        }
    }

    /** Sheet cutting options (spec/cli.md, {@code fresa cut}). */
    public record CuttingSettings(Path drawing, double kerfMm, String process, double leadInMm, double leadOutMm,
            String lead, double toleranceMm, String units, boolean paperMode, String post) {
        public CuttingSettings {
            Objects.requireNonNull(drawing, "drawing");
            Objects.requireNonNull(process, "process");
            Objects.requireNonNull(lead, "lead");
            Objects.requireNonNull(units, "units");
            Objects.requireNonNull(post, "post");
        }
    }

    /** Grading options (spec/cli.md, {@code fresa grade}); empty steps mean the system's own. */
    public record GradingSettings(Path outline, double baseSize, String sizes, boolean halfSizes, String system,
            OptionalDouble lengthStepMm, OptionalDouble widthStepMm, Optional<Vec2> originMm,
            double shrinkage, String shrinkageMode) {
        public GradingSettings {
            Objects.requireNonNull(outline, "outline");
            Objects.requireNonNull(sizes, "sizes");
            Objects.requireNonNull(system, "system");
            Objects.requireNonNull(lengthStepMm, "lengthStepMm");
            Objects.requireNonNull(widthStepMm, "widthStepMm");
            Objects.requireNonNull(originMm, "originMm");
            Objects.requireNonNull(shrinkageMode, "shrinkageMode");
        }
    }

    /** The sole mould job (issue 10 adds the tread figures). */
    public record SoleSettings(Path outline, double baseSize, String sizes, double cavityDepthMm, String post) {
        public SoleSettings {
            Objects.requireNonNull(outline, "outline");
            Objects.requireNonNull(sizes, "sizes");
            Objects.requireNonNull(post, "post");
        }
    }

    /** Output formats chosen for tasks that have no format option of their own. */
    public record OutputSettings(List<String> formats) {
        public static final OutputSettings DEFAULT = new OutputSettings(List.of("csv", "png"));

        public OutputSettings {
            formats = List.copyOf(formats);
        }
    }
}
