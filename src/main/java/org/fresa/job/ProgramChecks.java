package org.fresa.job;

import java.util.EnumSet;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.fresa.check.Failure;
import org.fresa.check.Limits;
import org.fresa.check.NcDialect;
import org.fresa.check.ProgramCheck;
import org.fresa.check.ToolLimits;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.MachiningWorkingstep;
import org.fresa.stepnc.Operation.OperationType;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.stepnc.Workpiece;
import org.fresa.toolpath.ToolpathPlanner;

/**
 * What each module's programs are checked against ({@link ProgramCheck}) before they are written,
 * and the refusal a planner reads when one fails: the file that is not written, the block and the
 * rule.
 */
public final class ProgramChecks {

    /** Operations whose tool goes straight down its axis: drills, reamers, taps, boring bars. */
    static final Set<OperationType> AXIAL = EnumSet.of(OperationType.DRILLING, OperationType.CENTER_DRILLING,
            OperationType.MULTISTEP_DRILLING, OperationType.COUNTER_SINKING, OperationType.REAMING,
            OperationType.BORING, OperationType.BACK_BORING, OperationType.TAPPING, OperationType.THREAD_DRILLING);

    /**
     * How far below the stock's bottom a through hole's drill may reach: its tip (a 118 degree point,
     * D/2 / tan 59 degrees) and 1 mm of breakthrough.
     */
    static final double BREAKTHROUGH_MM = 1;

    private ProgramChecks() {
    }

    /** A program that failed the check and is not written. */
    public static final class RefusedProgram extends Exception {
        private static final long serialVersionUID = 1L;
        private final transient Failure failure;

        public RefusedProgram(String file, Failure failure) {
            super(file + " not written: it fails the program check at " + failure.message());
            this.failure = failure;
        }

        public Failure failure() {
            return failure;
        }
    }

    /** Checks the program; returns it when it passes. */
    public static String require(String file, String program, NcDialect dialect, Limits limits) throws RefusedProgram {
        Optional<Failure> f = ProgramCheck.of(program, dialect, limits).failure();
        if (f.isPresent()) {
            throw new RefusedProgram(file, f.get());
        }
        return program;
    }

    /**
     * The pocket module's limits. The G-code posts: the stock below the pocket's top, the floor its
     * bottom with no breakthrough, the cutter not cutting at its centre (3 degrees). The 7M posts
     * write the thesis's programs, which plunge straight down at every depth pass (G01 G91 Z-):
     * they are checked with the thesis's cutter declared centre-cutting and asked to plunge (a
     * slot drill, as the NBH-65's pocket programs assume), in the 7M's frame whose zero is the
     * pocket's top (G54 Z = the top).
     */
    public static Limits pocket(PocketSettings s) {
        double r = s.toolDiameterMm() / 2;
        if (PocketService.SINUMERIK_7M_POSTS.contains(s.post())) {
            return Limits.milling().withHeights(0, s.zBottomMm() - s.zTopMm(), 0)
                    .withOtherTools(ToolLimits.centreCuttingPlunge().withRadiusMm(r)
                            .withKind("the thesis's slot drill, declared centre-cutting: the 7M posts plunge"));
        }
        // the planner's own entry limits: a plunge only for a centre-cutting tool asked to plunge,
        // else the entry angle the job states (3 degrees unless the planner says otherwise)
        ToolLimits tool = s.centreCutting() && "plunge".equals(s.entry())
                ? ToolLimits.centreCuttingPlunge().withKind("a centre-cutting tool asked to plunge")
                : ToolLimits.notCentreCutting().withEntryAngleDeg(s.entryAngleDeg());
        return Limits.milling().withHeights(s.zTopMm(), s.zBottomMm(), 0).withOtherTools(tool.withRadiusMm(r));
    }

    /**
     * A sole's tread programs: the stock below the mould's top face (z = 0), the floor the tread
     * depth. The job gives every tread tool a plunge feed: they are engravers that go straight
     * down into the groove, taken as centre-cutting tools asked to plunge.
     */
    public static Limits soleTread(JobSettings.SoleSettings s) {
        return Limits.milling().withHeights(0, -s.treadDepthMm(), 0)
                .withOtherTools(ToolLimits.centreCuttingPlunge().withKind("a tread engraver, given a plunge feed by the job"));
    }

    /**
     * A sole's cavity programs: the stock below the top face (z = 0), the floor the cavity depth,
     * the cavity tool a pocket cutter that does not cut at its centre (3 degrees), as the pocket
     * module's.
     */
    public static Limits soleCavity(JobSettings.SoleSettings s) {
        return Limits.milling().withHeights(0, -s.cavityDepthMm(), 0);
    }

    /** The dialect of a post's name ({@code linuxcnc}, ..., {@code 7m-compat}). */
    public static NcDialect dialect(String post) {
        return NcDialect.byPost(post).orElseThrow(() -> new IllegalArgumentException("no dialect for post " + post));
    }

    /**
     * A STEP-NC program's limits: each tool as its operations use it (drills, reamers, taps and
     * boring bars straight down; milling cutters not cutting at their centre, 3 degrees), the stock
     * the workpiece's block when the file gives one (the floor its bottom, with the deepest drill's
     * tip and {@link #BREAKTHROUGH_MM} below it), otherwise unbounded with no floor.
     */
    public static Limits stepnc(StepNcProgram program, ToolpathPlanner.Plan plan) {
        Limits l = Limits.milling();
        Map<Long, MachiningWorkingstep> byId = new HashMap<>();
        for (MachiningWorkingstep w : program.workingsteps()) {
            byId.put(w.instanceId(), w);
        }
        List<ToolpathSection> sections = plan.toolpath().sections();
        double deepestTipMm = 0;
        for (int i = 0; i < sections.size() && i < plan.steps().size(); i++) {
            ToolpathSection s = sections.get(i);
            MachiningWorkingstep w = byId.get(plan.steps().get(i).workingstepInstanceId());
            boolean axial = w != null && AXIAL.contains(w.operation().type());
            ToolLimits t = axial ? ToolLimits.drill() : ToolLimits.notCentreCutting();
            l = l.withTool(s.toolNumber(), t.withRadiusMm(s.toolDiameterMm() / 2));
            if (axial) {
                deepestTipMm = Math.max(deepestTipMm, s.toolDiameterMm() / 2 / Math.tan(Math.toRadians(59)));
            }
        }
        Optional<Workpiece.Block> block = program.workpieces().size() == 1 ? program.workpieces().get(0).block()
                : Optional.empty();
        if (block.isPresent()) {
            Limits.Stock stock = box(block.get());
            l = l.withStock(stock).withFloor(stock.minZMm(), deepestTipMm + BREAKTHROUGH_MM);
        }
        return l;
    }

    /** The block's bounding box in the workpiece frame. */
    static Limits.Stock box(Workpiece.Block b) {
        double[] min = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] max = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        Transform3 t = b.placement();
        for (int k = 0; k < 8; k++) {
            Vec3 c = t.applyToPoint(new Vec3((k & 1) * b.xMm(), ((k >> 1) & 1) * b.yMm(), ((k >> 2) & 1) * b.zMm()));
            double[] v = {c.x(), c.y(), c.z()};
            for (int i = 0; i < 3; i++) {
                min[i] = Math.min(min[i], v[i]);
                max[i] = Math.max(max[i], v[i]);
            }
        }
        return new Limits.Stock(min[0], min[1], min[2], max[0], max[1], max[2]);
    }
}
