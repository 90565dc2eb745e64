package org.fresa.cell;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalDouble;
import org.fresa.geom.Transform3;
import org.fresa.kin.Robot;
import org.fresa.model.Placement;
import org.fresa.setting.SettingRanges;
import org.fresa.stepnc.MachiningWorkingstep;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.stepnc.Tool;
import org.fresa.toolpath.ToolpathPlanner;

/**
 * The tool frame (TCP) of each workingstep in the flange frame: spindle * Tz(tool length)
 * (spec/cli.md), so that a tool change changes the TCP.
 *
 * <p>The spindle is {@code --spindle} (or the job's), else the robot file's tool frame, else the
 * flange itself, which is said in one warning. The tool length is {@code --tool-length} (or the
 * job's), else the STEP-NC tool's {@code overall_assembly_length}, else its cutting component's
 * {@code tool_offset_length}; a tool with neither is refused, as its tip would be put at the
 * spindle nose and the spindle driven into the part.
 */
public final class RobotTools {

    private RobotTools() {}

    /**
     * The TCPs.
     *
     * @param spindle the spindle nose in the flange frame
     * @param tcpByLabel each workingstep's TCP in the flange frame
     * @param warnings one sentence each, for the planner
     * @param toolpath the plan's toolpath, a section relabelled {@code "id [Tn]"} where workingsteps
     *     sharing an id use tools of different lengths, so that each label has one TCP
     */
    public record Frames(
            Transform3 spindle,
            Map<String, Transform3> tcpByLabel,
            List<String> warnings,
            org.fresa.model.Toolpath toolpath) {
        public Frames {
            tcpByLabel = Map.copyOf(tcpByLabel);
            warnings = List.copyOf(warnings);
        }
    }

    /** What the planner said about the tool. */
    public record Choice(Optional<Placement> spindle, OptionalDouble toolLengthMm) {
        public static final Choice NONE = new Choice(Optional.empty(), OptionalDouble.empty());

        public Choice {
            java.util.Objects.requireNonNull(spindle, "spindle");
            java.util.Objects.requireNonNull(toolLengthMm, "toolLengthMm");
        }
    }

    /** The warning when no spindle is given anywhere. */
    public static final String NO_SPINDLE = "no spindle given (--spindle, the job or the robot file): the tool tip"
            + " is taken as the flange plus the tool's length along the flange's z axis";

    /** The spindle in the flange frame, and the warning when there is none. */
    public static Transform3 spindle(Robot robot, Choice choice, List<String> warnings) {
        if (choice.spindle().isPresent()) {
            return choice.spindle().get().toTransform();
        }
        if (!robot.tool().equals(Transform3.IDENTITY)) {
            return robot.tool();
        }
        warnings.add(NO_SPINDLE);
        return Transform3.IDENTITY;
    }

    /** The TCP of a spindle and a tool length. */
    public static Transform3 tcp(Transform3 spindle, double toolLengthMm) {
        return spindle.times(Transform3.translation(0, 0, toolLengthMm));
    }

    /**
     * The TCP of each planned workingstep of a STEP-NC program.
     *
     * @throws org.fresa.model.CamInputException when a tool has no length and none is given
     */
    public static Frames of(Robot robot, Choice choice, StepNcProgram program, ToolpathPlanner.Plan plan, String source)
            throws org.fresa.model.CamInputException {
        List<String> warnings = new ArrayList<>();
        Transform3 spindle = spindle(robot, choice, warnings);
        Map<Long, MachiningWorkingstep> byId = new LinkedHashMap<>();
        for (MachiningWorkingstep ws : program.workingsteps()) {
            byId.put(ws.instanceId(), ws);
        }
        List<Transform3> tcpOfSection = new ArrayList<>();
        for (ToolpathPlanner.PlannedStep step : plan.steps()) {
            double length;
            if (choice.toolLengthMm().isPresent()) {
                length = choice.toolLengthMm().getAsDouble();
            } else {
                MachiningWorkingstep ws = byId.get(step.workingstepInstanceId());
                Optional<Tool> tool =
                        ws == null ? Optional.empty() : ws.operation().tool();
                OptionalDouble l = tool.isPresent() ? length(tool.get()) : OptionalDouble.empty();
                if (l.isEmpty()) {
                    throw new org.fresa.model.CamInputException(
                            source,
                            "workingstep '" + step.label() + "': its tool"
                                    + tool.map(t -> " '" + t.id() + "'").orElse("")
                                    + " has no overall_assembly_length or"
                                    + " tool_offset_length, so its tip cannot be put on the part: give --tool-length");
                }
                length = l.getAsDouble();
            }
            tcpOfSection.add(tcp(spindle, length));
        }
        return labelled(spindle, plan.toolpath().sections(), tcpOfSection, warnings);
    }

    /** The frames of sections with their TCPs, a shared label split by tool where the TCPs differ. */
    static Frames labelled(
            Transform3 spindle,
            List<org.fresa.model.ToolpathSection> sections,
            List<Transform3> tcpOfSection,
            List<String> warnings) {
        Map<String, java.util.Set<Transform3>> tcpsOfLabel = new LinkedHashMap<>();
        for (int i = 0; i < sections.size(); i++) {
            tcpsOfLabel
                    .computeIfAbsent(sections.get(i).label(), k -> new java.util.HashSet<>())
                    .add(tcpOfSection.get(i));
        }
        Map<String, Transform3> tcp = new LinkedHashMap<>();
        List<org.fresa.model.ToolpathSection> relabelled = new ArrayList<>();
        for (int i = 0; i < sections.size(); i++) {
            org.fresa.model.ToolpathSection sec = sections.get(i);
            String label = sec.label();
            if (tcpsOfLabel.get(label).size() > 1) {
                // one id, tools of different lengths: each tool's points must carry its own TCP
                label = label + " [T" + sec.toolNumber() + "]";
            }
            tcp.put(label, tcpOfSection.get(i));
            relabelled.add(sec.withLabel(label));
        }
        return new Frames(spindle, tcp, warnings, new org.fresa.model.Toolpath(relabelled));
    }

    /** The tool's length from the spindle nose to the tip, when the file gives it (and it is sane). */
    static OptionalDouble length(Tool t) {
        OptionalDouble l =
                t.overallAssemblyLengthMm().isPresent() ? t.overallAssemblyLengthMm() : t.toolOffsetLengthMm();
        if (l.isPresent() && SettingRanges.Robot.TOOL_LENGTH.contains(l.getAsDouble())) {
            return l;
        }
        return OptionalDouble.empty();
    }
}
