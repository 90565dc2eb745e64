package org.fresa.ui;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.TreeSet;
import org.fresa.chart.PlotScene;
import org.fresa.chart.ViewPlane;
import org.fresa.geom.Arc2;
import org.fresa.geom.Box2;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.job.ToolpathService;
import org.fresa.model.ArcGeometry;
import org.fresa.model.CycleTime;
import org.fresa.model.ExactDecimal;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.Executable;
import org.fresa.stepnc.Feature;
import org.fresa.stepnc.MachiningWorkingstep;
import org.fresa.stepnc.Operation;
import org.fresa.stepnc.Profile;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.stepnc.Technology;
import org.fresa.stepnc.Tool;
import org.fresa.stepnc.TravelPath;
import org.fresa.stepnc.Workpiece;
import org.fresa.stepnc.Workplan;
import org.fresa.toolpath.ToolpathPlanner;

/**
 * The STEP-NC tab's state without Swing: the program read, its tree (project, workplans,
 * workingsteps, then skipped workingsteps and unknown entities, never hidden), the details of
 * the selected workingstep with units, and a plot of the workpiece block and the feature
 * outline seen along the feature axis.
 *
 * <p>Once the program is planned ({@link #planned}), the plot also shows the selected
 * workingstep's toolpath over its feature: rapids and feeds in their own styles, arcs as arcs
 * when they lie in the view plane, one depth layer or all of them, and a replay position: the
 * slider value 0..{@link #REPLAY_STEPS} is the fraction of the shown moves' machining time, the
 * tool is drawn there at its diameter and the path travelled so far is highlighted. Cycle times
 * count feeds at their feed and rapids at {@link ToolpathService#RAPID_MM_PER_MIN}, without
 * acceleration, per workingstep and for the whole program.
 */
final class StepNcViewModel {

    /** A node of the tree; {@code workingstep} is set on workingstep leaves. */
    record Node(String label, List<Node> children, Optional<MachiningWorkingstep> workingstep) {
        Node {
            Objects.requireNonNull(label);
            children = List.copyOf(children);
            Objects.requireNonNull(workingstep);
        }

        static Node leaf(String label) {
            return new Node(label, List.of(), Optional.empty());
        }

        @Override
        public String toString() {
            return label;
        }
    }

    /** The replay slider's range: 0 (before the first move) to this (the end of the last). */
    static final int REPLAY_STEPS = 200;
    /** Rapid rate of the cycle-time estimate (mm/min). */
    static final double RAPID_MM_PER_MIN = ToolpathService.RAPID_MM_PER_MIN;
    /** Depths closer than this are one layer (mm). */
    private static final double LAYER_TOLERANCE_MM = 1e-6;
    /** Chord tolerance for arcs outside the view plane (mm). */
    private static final double CHORD_MM = 0.01;

    /**
     * A depth layer of a section: in-plane feed moves at {@code depthMm} below the feature's top,
     * measured along the feature axis.
     */
    record Layer(int number, double depthMm) {}

    /** Moves run from {@code start}. */
    record Shown(Vec3 start, List<Move> moves) {
        Shown {
            Objects.requireNonNull(start);
            moves = List.copyOf(moves);
        }
    }

    /**
     * Where the tool is at a replay value.
     *
     * @param position tool tip (mm, workpiece frame)
     * @param moveIndex the move being run, 0-based within the shown moves (-1 before the first)
     * @param timeS time since the start of the shown moves
     * @param totalS time of all shown moves
     * @param fraction how far into the move (0..1)
     */
    record ReplayPoint(Vec3 position, int moveIndex, double timeS, double totalS, double fraction) {}

    private Optional<StepNcProgram> program = Optional.empty();
    private Optional<MachiningWorkingstep> selected = Optional.empty();
    private Optional<ToolpathPlanner.Plan> plan = Optional.empty();
    // what the job's run says of the plan, in its words
    private List<String> told = List.of();
    /** 0 all layers, else the layer number (1-based) */
    private int layer;

    private int replay = REPLAY_STEPS;

    Optional<StepNcProgram> program() {
        return program;
    }

    void load(StepNcProgram p) {
        program = Optional.of(p);
        plan = Optional.empty();
        selected = p.workingsteps().isEmpty()
                ? Optional.empty()
                : Optional.of(p.workingsteps().get(0));
        layer = 0;
        replay = REPLAY_STEPS;
    }

    /** The program's toolpaths, planned in the background after {@link #load}. */
    void planned(ToolpathPlanner.Plan p) {
        planned(p, p.problems());
    }

    /**
     * The program's toolpaths with what the job's run says of them ({@link #problemsOf}), both
     * made in the background after {@link #load}.
     */
    void planned(ToolpathPlanner.Plan p, List<String> said) {
        plan = Optional.of(Objects.requireNonNull(p));
        told = List.copyOf(said);
        layer = 0;
        replay = REPLAY_STEPS;
    }

    /**
     * Every problem the job's run says of the program: the planner's (workingsteps not planned,
     * parts of them not milled), and for a toolpath job what {@code fresa toolpath} adds.
     */
    WarningList problems() {
        return plan.isEmpty() ? WarningList.of(List.of()) : WarningList.of(told);
    }

    /**
     * What a run of the job says of the planned program, from the service that runs it: a job
     * that writes the 3-axis program ({@code toolpath}) says what {@link
     * ToolpathService#problems} says (the workingsteps it leaves for another setup, the program
     * check's refusal); any other (a description, a robot, which keeps every tool axis) the
     * planner's problems.
     */
    static List<String> problemsOf(
            org.fresa.job.Job job,
            java.nio.file.Path file,
            ToolpathService.Planned planned,
            org.fresa.job.JobSettings.StepNcSettings settings)
            throws java.io.IOException {
        if (job.runs().contains(org.fresa.job.JobTask.TOOLPATH)) {
            return ToolpathService.problems(file, planned, settings.post(), settings.choices());
        }
        return planned.plan().problems();
    }

    /**
     * The workingstep a problem's text names: by its instance ("(#123)") or, failing that, by its
     * name in quotes ("workingstep 'WS FINISH POCKET1'").
     */
    Optional<MachiningWorkingstep> workingstepNamedIn(String text) {
        if (program.isEmpty()) {
            return Optional.empty();
        }
        List<MachiningWorkingstep> all = program.get().workingsteps();
        Optional<MachiningWorkingstep> byInstance = all.stream()
                .filter(ws -> text.contains("(#" + ws.instanceId() + ")"))
                .findFirst();
        return byInstance.isPresent()
                ? byInstance
                : all.stream().filter(ws -> text.contains("'" + ws.id() + "'")).findFirst();
    }

    Optional<ToolpathPlanner.Plan> plan() {
        return plan;
    }

    Optional<MachiningWorkingstep> selected() {
        return selected;
    }

    void select(Optional<MachiningWorkingstep> ws) {
        if (!ws.equals(selected)) {
            layer = 0;
            replay = REPLAY_STEPS;
        }
        selected = ws;
    }

    /** The selected workingstep's section, when it is selected and planned. */
    Optional<ToolpathSection> section() {
        if (selected.isEmpty() || plan.isEmpty()) {
            return Optional.empty();
        }
        return plan.get().sectionOf(selected.get().instanceId());
    }

    /** The selected section's depth layers, top first; empty when it has none (drilling). */
    List<Layer> layers() {
        return section().map(s -> layersOf(s, selected.get().feature())).orElse(List.of());
    }

    /** The layer selector's entries: "All layers", then one per layer. */
    List<String> layerChoices() {
        List<String> out = new ArrayList<>();
        List<Layer> ls = layers();
        out.add(ls.isEmpty() ? "All moves" : "All " + ls.size() + " layers");
        for (Layer l : ls) {
            out.add("Layer " + l.number() + " of " + ls.size() + ": " + n(l.depthMm()) + " mm deep");
        }
        return out;
    }

    /** 0 for all layers, else the layer number. */
    int layer() {
        return layer;
    }

    /** Shows one layer (1..n) or all (0); the replay goes to the end of what is shown. */
    void selectLayer(int number) {
        if (number < 0 || number > layers().size()) {
            throw new IllegalArgumentException("no layer " + number + " (0.." + layers().size() + ")");
        }
        layer = number;
        replay = REPLAY_STEPS;
    }

    int replay() {
        return replay;
    }

    /** The replay slider's value, clamped to 0..{@link #REPLAY_STEPS}. */
    void setReplay(int value) {
        replay = Math.max(0, Math.min(REPLAY_STEPS, value));
    }

    /** The moves of the chosen layer (or all), each layer with the moves that lead into it. */
    Optional<Shown> shown() {
        Optional<ToolpathSection> s = section();
        if (s.isEmpty()) {
            return Optional.empty();
        }
        ToolpathSection sec = s.get();
        if (layer == 0) {
            return Optional.of(new Shown(sec.start(), sec.moves()));
        }
        int[] of = layerOfMoves(sec, selected.get().feature());
        List<Move> moves = new ArrayList<>();
        Vec3 start = null;
        Vec3 at = sec.start();
        for (int i = 0; i < sec.moves().size(); i++) {
            if (of[i] == layer) {
                if (start == null) {
                    start = at;
                }
                moves.add(sec.moves().get(i));
            }
            at = sec.moves().get(i).end();
        }
        return Optional.of(new Shown(start == null ? sec.start() : start, moves));
    }

    /** Where the tool is at the current replay value. */
    Optional<ReplayPoint> replayPoint() {
        return shown().map(sh -> replayAt(sh, (double) replay / REPLAY_STEPS));
    }

    /** The point reached after {@code fraction} (0..1) of the moves' machining time. */
    static ReplayPoint replayAt(Shown sh, double fraction) {
        double total = CycleTime.of(sh.start(), sh.moves(), RAPID_MM_PER_MIN).seconds();
        double t = total * fraction;
        if (sh.moves().isEmpty() || fraction <= 0) {
            return new ReplayPoint(sh.start(), -1, 0, total, 0);
        }
        Vec3 at = sh.start();
        double elapsed = 0;
        for (int i = 0; i < sh.moves().size(); i++) {
            Move m = sh.moves().get(i);
            double dt = CycleTime.seconds(at, m, RAPID_MM_PER_MIN);
            boolean last = i == sh.moves().size() - 1;
            if (elapsed + dt >= t || last) {
                double f = dt > 0 ? Math.max(0, Math.min(1, (t - elapsed) / dt)) : 1;
                if (fraction >= 1 && last) {
                    f = 1;
                }
                return new ReplayPoint(pointOn(at, m, f), i, Math.min(t, total), total, f);
            }
            elapsed += dt;
            at = m.end();
        }
        throw new IllegalStateException("unreachable");
    }

    /** The point at {@code fraction} of the move's length (its time, as the rate is constant). */
    static Vec3 pointOn(Vec3 from, Move m, double fraction) {
        if (fraction >= 1) {
            return m.end();
        }
        if (m instanceof Move.Circular c) {
            return ArcGeometry.of(from, c).pointAt(fraction);
        }
        return from.interpolate(m.end(), fraction);
    }

    /** A line saying where the replay is, e.g. "12.3 s of 50.4 s: move 5 of 29, feed 2400 mm/min at (x, y, z) mm". */
    String replayText() {
        Optional<Shown> sh = shown();
        if (sh.isEmpty()) {
            return plan.isEmpty() && program.isPresent() ? "Planning toolpaths..." : "No toolpath for this selection";
        }
        ReplayPoint r = replayAt(sh.get(), (double) replay / REPLAY_STEPS);
        String move;
        if (r.moveIndex() < 0) {
            move = "before the first move";
        } else {
            Move m = sh.get().moves().get(r.moveIndex());
            String kind = kindText(m);
            move = "move " + (r.moveIndex() + 1) + " of " + sh.get().moves().size() + " (" + kind + ")";
        }
        return seconds(r.timeS()) + " of " + seconds(r.totalS()) + ": " + move + ", tool at " + v(r.position()) + " mm";
    }

    /** How the replay line names a move: "rapid", "feed 300 mm/min", "dwell 1.5 s"... */
    static String kindText(Move m) {
        if (m instanceof Move.Rapid) {
            return "rapid";
        }
        if (m instanceof Move.Linear l) {
            return "feed " + n(l.feedMmPerMin()) + " mm/min";
        }
        if (m instanceof Move.Circular c) {
            return "arc, feed " + n(c.feedMmPerMin()) + " mm/min";
        }
        if (m instanceof Move.Dwell d) {
            return "dwell " + n(d.seconds()) + " s";
        }
        if (m instanceof Move.SpindleStop) {
            return "spindle stop";
        }
        Move.SpindleStart on = (Move.SpindleStart) m;
        return "spindle " + n(on.rpm()) + " rpm " + (on.clockwise() ? "clockwise" : "counter-clockwise");
    }

    /** The selected workingstep's cycle time, when planned. */
    Optional<CycleTime> workingstepTime() {
        return section().map(s -> CycleTime.of(s, RAPID_MM_PER_MIN));
    }

    /** The whole program's cycle time, when planned. */
    Optional<CycleTime> programTime() {
        // several texts ask for it on every selection: a big program's sum is kept with its plan
        if (programTime == null || programTimeOf != plan.orElse(null)) {
            programTimeOf = plan.orElse(null);
            programTime = plan.map(StepNcViewModel::programTimeOf);
        }
        return programTime;
    }

    private Optional<CycleTime> programTime;
    private ToolpathPlanner.Plan programTimeOf;

    /** The cycle time of a whole plan (any thread). */
    static CycleTime programTimeOf(ToolpathPlanner.Plan p) {
        CycleTime t = CycleTime.ZERO;
        for (ToolpathSection s : p.toolpath().sections()) {
            t = t.plus(CycleTime.of(s, RAPID_MM_PER_MIN));
        }
        return t;
    }

    /** The plan with its cycle time computed off the event thread. */
    void planned(ToolpathPlanner.Plan p, CycleTime total, List<String> said) {
        planned(p, said);
        programTimeOf = p;
        programTime = Optional.of(total);
    }

    /** The cycle-time lines: this workingstep, the program, and the assumptions. */
    List<String> cycleTime() {
        List<String> out = new ArrayList<>();
        if (plan.isEmpty()) {
            return out;
        }
        ToolpathPlanner.Plan p = plan.get();
        workingstepTime()
                .ifPresentOrElse(
                        t -> out.add("Cycle time of this workingstep: " + timeText(t)),
                        () -> out.add(
                                selected.isPresent() ? "This workingstep was not planned" : "No workingstep selected"));
        out.add("Cycle time of the program (" + p.planned() + " of " + p.workingsteps() + " workingsteps): "
                + timeText(programTime().orElseThrow()));
        out.add("Feeds at their feed rate, rapids at " + n(RAPID_MM_PER_MIN) + " mm/min, no acceleration");
        return out;
    }

    /** One line: this workingstep's and the program's cycle time. */
    String cycleTimeShort() {
        if (plan.isEmpty()) {
            return program.isPresent() ? "Planning toolpaths..." : " ";
        }
        String ws = workingstepTime().map(t -> seconds(t.seconds())).orElse("not planned");
        return "Cycle time: this workingstep " + ws + ", program "
                + seconds(programTime().orElseThrow().seconds()) + " (rapids at " + n(RAPID_MM_PER_MIN) + " mm/min)";
    }

    private static String timeText(CycleTime t) {
        return seconds(t.seconds()) + " (feed " + n(t.feedLengthMm()) + " mm in " + seconds(t.feedSeconds())
                + ", rapid " + n(t.rapidLengthMm()) + " mm in " + seconds(t.rapidSeconds())
                + (t.dwellSeconds() > 0 ? ", dwells " + seconds(t.dwellSeconds()) : "") + ")";
    }

    /** "50.4 s", or "3 min 05.2 s" from a minute on. */
    static String seconds(double s) {
        if (s < 60) {
            return String.format(Locale.ROOT, "%.1f s", s);
        }
        long min = (long) Math.floor(s / 60);
        return String.format(Locale.ROOT, "%d min %04.1f s", min, s - 60 * min);
    }

    /** Depth below the feature's top along its axis (mm, positive down). */
    static double depthOf(Vec3 p, Feature f) {
        return -p.minus(f.location()).dot(f.axis().normalized());
    }

    private static boolean inPlane(Vec3 from, Move m, Feature f) {
        return !(m instanceof Move.Rapid)
                && Math.abs(depthOf(from, f) - depthOf(m.end(), f)) < LAYER_TOLERANCE_MM
                && CycleTime.lengthMm(from, m) > LAYER_TOLERANCE_MM;
    }

    /** The depths at which the section feeds in the feature's plane, top first. */
    static List<Layer> layersOf(ToolpathSection s, Feature f) {
        TreeSet<Double> depths = new TreeSet<>();
        Vec3 at = s.start();
        for (Move m : s.moves()) {
            if (inPlane(at, m, f)) {
                double d = depthOf(m.end(), f);
                if (depths.stream().noneMatch(x -> Math.abs(x - d) < LAYER_TOLERANCE_MM)) {
                    depths.add(d);
                }
            }
            at = m.end();
        }
        List<Layer> out = new ArrayList<>();
        int k = 1;
        for (double d : depths) {
            out.add(new Layer(k++, d + 0.0));
        }
        return out;
    }

    /**
     * The layer number of each move: the layer of the next in-plane feed at or after it (so the
     * moves down into a layer belong to it), the last layer for the moves after the last one, 0
     * when the section has no layers.
     */
    static int[] layerOfMoves(ToolpathSection s, Feature f) {
        List<Layer> layers = layersOf(s, f);
        int n = s.moves().size();
        int[] of = new int[n];
        int[] own = new int[n];
        Vec3 at = s.start();
        for (int i = 0; i < n; i++) {
            Move m = s.moves().get(i);
            if (inPlane(at, m, f)) {
                double d = depthOf(m.end(), f);
                for (Layer l : layers) {
                    if (Math.abs(l.depthMm() - d) < LAYER_TOLERANCE_MM) {
                        own[i] = l.number();
                    }
                }
            }
            at = m.end();
        }
        int next = 0;
        int lastSeen = 0;
        for (int i = 0; i < n; i++) {
            if (own[i] != 0) {
                lastSeen = own[i];
            }
        }
        for (int i = n - 1; i >= 0; i--) {
            if (own[i] != 0) {
                next = own[i];
            }
            of[i] = next != 0 ? next : lastSeen;
        }
        return of;
    }

    /**
     * The moves seen along the dropped axis, rapids and feeds apart; arcs about the view axis as
     * arcs (full turns as circles), other arcs as chords.
     */
    static void drawMoves(Vec3 start, List<Move> moves, ViewPlane drop, List<Curve2> feeds, List<Curve2> rapids) {
        Vec3 at = start;
        for (Move m : moves) {
            (m instanceof Move.Rapid ? rapids : feeds).addAll(curvesOf(at, m, drop, 1));
            at = m.end();
        }
    }

    /** The part [0, fraction] of one move, in the view plane. */
    static List<Curve2> curvesOf(Vec3 from, Move m, ViewPlane drop, double fraction) {
        List<Curve2> out = new ArrayList<>();
        if (fraction <= 0) {
            return out;
        }
        if (m instanceof Move.Circular c) {
            ArcGeometry g = ArcGeometry.of(from, c);
            double along = c.normal().dot(drop.viewAxis());
            if (Math.abs(Math.abs(along) - 1) < 1e-9 && g.radiusMm() > 0) {
                double sense = Math.signum(along) * (drop.keepsSense() ? 1 : -1);
                double sweep = g.sweepRad() * fraction * sense;
                Vec2 center = drop.project(c.center());
                double a0 = drop.project(from).minus(center).angleRad();
                double r = g.radiusMm();
                double left = sweep;
                while (Math.abs(left) > 1e-12) {
                    double step = Math.abs(left) > 2 * Math.PI ? Math.copySign(2 * Math.PI, left) : left;
                    if (Math.abs(step) >= 2 * Math.PI - 1e-9) {
                        Vec2 p = center.plus(Vec2.ofAngle(a0).times(r));
                        out.add(new Arc2(center, p, p, step > 0));
                    } else {
                        out.add(Arc2.ofAngles(center, r, a0, step));
                    }
                    a0 += step;
                    left -= step;
                }
                return out;
            }
            Vec2 a = drop.project(from);
            for (Vec3 q : g.points(CHORD_MM)) {
                Vec2 b = drop.project(q);
                if (!a.equals(b)) {
                    out.add(Segment2.of(a, b));
                }
                a = b;
            }
            if (fraction < 1) {
                // chords up to the replay point only
                Vec2 end = drop.project(g.pointAt(fraction));
                List<Curve2> cut = new ArrayList<>();
                Vec2 p0 = drop.project(from);
                int keep = (int) Math.floor(out.size() * fraction);
                cut.addAll(out.subList(0, Math.min(keep, out.size())));
                Vec2 last = cut.isEmpty() ? p0 : cut.get(cut.size() - 1).end();
                if (!last.equals(end)) {
                    cut.add(Segment2.of(last, end));
                }
                return cut;
            }
            return out;
        }
        Vec2 a = drop.project(from);
        Vec2 b = drop.project(pointOn(from, m, fraction));
        if (!a.equals(b)) {
            out.add(Segment2.of(a, b));
        }
        return out;
    }

    /** The tree: project > workplans > workingsteps; skipped workingsteps; unknown entities. */
    Optional<Node> tree() {
        return program.map(StepNcViewModel::treeOf);
    }

    /** The tree of a program; touches no view-model state, so the tab builds it off the event thread. */
    static Node treeOf(StepNcProgram p) {
        List<Node> top = new ArrayList<>();
        int[] counter = {0};
        p.mainWorkplan().ifPresent(w -> top.add(workplanNode(w, counter)));
        if (!p.skipped().isEmpty()) {
            List<Node> sk = new ArrayList<>();
            for (StepNcProgram.Skipped s : p.skipped()) {
                sk.add(new Node(
                        "#" + s.instanceId() + " " + s.id() + " (" + s.reason() + ")", List.of(), s.workingstep()));
            }
            top.add(new Node("Skipped workingsteps (" + p.skipped().size() + ")", sk, Optional.empty()));
        }
        if (!p.unknownEntities().isEmpty()) {
            List<Node> un = new ArrayList<>();
            p.unknownEntities().forEach((k, c) -> un.add(Node.leaf(k + " x" + c)));
            top.add(new Node(
                    "Entities not interpreted (" + p.unknownEntities().size() + " types)", un, Optional.empty()));
        }
        if (!p.spellings().isEmpty() || !p.warnings().isEmpty()) {
            List<Node> notes = new ArrayList<>();
            p.spellings().forEach(s -> notes.add(Node.leaf("seen: " + s)));
            p.warnings().forEach(s -> notes.add(Node.leaf("warning: " + s)));
            top.add(new Node("Notes (" + notes.size() + ")", notes, Optional.empty()));
        }
        return new Node(
                "Project '" + p.projectId() + "' (" + p.source() + ", " + p.instanceCount() + " instances)",
                top,
                Optional.empty());
    }

    private static Node workplanNode(Workplan w, int[] counter) {
        List<Node> children = new ArrayList<>();
        for (Executable e : w.elements()) {
            if (e instanceof Workplan sub) {
                children.add(workplanNode(sub, counter));
            } else if (e instanceof MachiningWorkingstep ws) {
                counter[0]++;
                children.add(new Node(
                        counter[0] + ". " + ws.id() + ": " + ws.operation().entity() + " on "
                                + ws.feature().entity(),
                        List.of(),
                        Optional.of(ws)));
            } else if (e instanceof Executable.Other o) {
                children.add(Node.leaf("#" + o.instanceId() + " " + o.entity() + " (not interpreted)"));
            }
        }
        String setup = w.setup().map(s -> ", setup '" + s.id() + "'").orElse("");
        return new Node("Workplan '" + w.id() + "'" + setup, children, Optional.empty());
    }

    /** The selected workingstep's feature, operation, strategy, tool and technology, with units. */
    List<String> details() {
        List<String> out = new ArrayList<>();
        if (selected.isEmpty()) {
            program.ifPresent(p -> {
                out.add(p.source() + ": " + p.workingsteps().size() + " workingsteps, "
                        + p.skipped().size() + " skipped");
                for (Workpiece w : p.workpieces()) {
                    out.add("Workpiece '" + w.id() + "'"
                            + w.material().map(m -> ", " + m).orElse("")
                            + w.block()
                                    .map(b -> ", block " + n(b.xMm()) + " x " + n(b.yMm()) + " x " + n(b.zMm()) + " mm")
                                    .orElse(""));
                }
            });
            return out;
        }
        MachiningWorkingstep ws = selected.get();
        Feature f = ws.feature();
        out.add("Workingstep #" + ws.instanceId() + " '" + ws.id() + "'");
        out.add("Feature: " + f.entity() + " '" + f.id() + "' (#" + f.instanceId() + ")");
        out.add("  location " + v(f.location()) + " mm, axis " + v(f.axis()));
        f.depthMm().ifPresent(d -> out.add("  depth " + n(d) + " mm"));
        f.diameterMm().ifPresent(d -> out.add("  diameter " + n(d) + " mm"));
        f.bottomCondition().ifPresent(b -> out.add("  bottom " + b));
        f.orthogonalRadiusMm().ifPresent(r -> out.add("  corner radius " + n(r) + " mm"));
        f.profile().ifPresent(pr -> out.add("  profile " + profileText(pr)));
        Operation o = ws.operation();
        out.add("Operation: " + o.entity() + " '" + o.id() + "' (#" + o.instanceId() + ")");
        o.strategy().ifPresent(s -> {
            String overlap = s.overlapFraction().isPresent()
                    ? ", overlap " + n(s.overlapFraction().getAsDouble() * 100) + " % of the tool diameter (written as "
                            + s.overlapInterpretation().orElse("?") + " "
                            + n(s.overlap().orElse(0)) + ")"
                    : "";
            out.add("  strategy " + s.entity() + overlap
                    + s.rotationDirection().map(r -> ", " + r).orElse("")
                    + s.cutmode().map(c -> ", " + c).orElse(""));
        });
        mm(out, "  axial cutting depth", o.axialCuttingDepthMm());
        mm(out, "  radial cutting depth", o.radialCuttingDepthMm());
        mm(out, "  allowance side", o.allowanceSideMm());
        mm(out, "  allowance bottom", o.allowanceBottomMm());
        mm(out, "  cutting depth", o.cuttingDepthMm());
        mm(out, "  retract plane", o.retractPlaneMm());
        o.approach().ifPresent(a -> out.add("  approach " + a.entity()));
        o.retract().ifPresent(a -> out.add("  retract " + a.entity()));
        o.tool().ifPresent(t -> toolText(out, t));
        Technology t = o.technology();
        out.add("Technology:");
        t.feedrate()
                .ifPresent(fd -> out.add("  feed " + n(fd) + " " + unit(t.feedrateUnit())
                        + t.feedMmPerMin().stream()
                                .mapToObj(x -> " = " + n(x) + " mm/min")
                                .findFirst()
                                .orElse("")));
        t.cutSpeed().ifPresent(c -> out.add("  cutting speed " + n(c) + " " + t.cutSpeedUnit()));
        t.spindle()
                .ifPresent(s -> out.add("  spindle " + n(s) + " " + t.spindleUnit()
                        + t.spindleRpm().stream()
                                .mapToObj(x -> " = " + n(x) + " rpm")
                                .findFirst()
                                .orElse("")
                        + (t.spindleClockwise() ? ", clockwise" : "")));
        toolpathText(out, ws);
        return out;
    }

    private void toolpathText(List<String> out, MachiningWorkingstep ws) {
        if (plan.isEmpty()) {
            out.add("Toolpath: planning...");
            return;
        }
        Optional<ToolpathPlanner.PlannedStep> step = plan.get().steps().stream()
                .filter(s -> s.workingstepInstanceId() == ws.instanceId())
                .findFirst();
        Optional<ToolpathSection> sec = section();
        if (step.isEmpty() || sec.isEmpty()) {
            out.add("Toolpath: not planned");
            String key = "(#" + ws.instanceId() + ")";
            plan.get().problems().stream().filter(p -> p.contains(key)).forEach(p -> out.add("  " + p));
            return;
        }
        out.add("Toolpath: T" + sec.get().toolNumber() + " D" + n(sec.get().toolDiameterMm()) + " mm, "
                + sec.get().moves().size() + " moves, " + layers().size() + " layers");
        out.add("  " + step.get().feed().note());
        cycleTime().forEach(l -> out.add("  " + l));
    }

    private static void toolText(List<String> out, Tool t) {
        out.add("Tool: '" + t.id() + "' " + t.body() + " (#" + t.instanceId() + ")");
        mm(out, "  diameter", t.diameterMm());
        mm(out, "  edge radius", t.edgeRadiusMm());
        mm(out, "  cutting edge length", t.cuttingEdgeLengthMm());
        mm(out, "  overall assembly length", t.overallAssemblyLengthMm());
        mm(out, "  tool offset length", t.toolOffsetLengthMm());
        t.teeth().ifPresent(k -> out.add("  teeth " + k));
    }

    private static String profileText(Profile p) {
        if (p instanceof Profile.Rectangular r) {
            return p.entity() + " " + n(r.lengthMm()) + " x " + n(r.widthMm()) + " mm";
        } else if (p instanceof Profile.Circular c) {
            return p.entity() + " diameter " + n(c.diameterMm()) + " mm";
        } else if (p instanceof Profile.Ngon g) {
            return p.entity() + " " + g.sides() + " sides, diameter " + n(g.diameterMm()) + " mm";
        } else if (p instanceof Profile.General g) {
            return p.entity() + " (" + g.curveEntity() + ", " + g.segments().size() + " segments)";
        } else if (p instanceof Profile.U u) {
            return p.entity() + " width " + n(u.widthMm()) + " mm";
        } else if (p instanceof Profile.Linear l) {
            return p.entity() + " length " + n(l.lengthMm()) + " mm";
        }
        return p.entity() + " (not drawn)";
    }

    private static String unit(String u) {
        return u.equals("unstated") ? "(unit not stated by the file's writer)" : u;
    }

    private static void mm(List<String> out, String label, OptionalDouble v) {
        v.ifPresent(d -> out.add(label + " " + n(d) + " mm"));
    }

    /**
     * The workpiece block and the selected feature's outline, seen along the feature axis: from
     * above (XY) for a feature on the top face, from the front (XZ) or the side (YZ) otherwise.
     */
    PlotScene plot() {
        if (program.isEmpty()) {
            return PlotScene.empty("STEP-NC");
        }
        ViewPlane drop =
                selected.map(ws -> ViewPlane.along(ws.feature().axis())).orElse(ViewPlane.TOP_XY);
        PlotScene scene = PlotScene.empty(drop.title()).withAxes(drop.axes());
        for (Workpiece w : program.get().workpieces()) {
            if (w.block().isPresent()) {
                Workpiece.Block b = w.block().get();
                List<Vec2> pts = new ArrayList<>();
                for (int i = 0; i < 8; i++) {
                    Vec3 c = b.placement()
                            .applyToPoint(
                                    new Vec3((i & 1) * b.xMm(), ((i >> 1) & 1) * b.yMm(), ((i >> 2) & 1) * b.zMm()));
                    pts.add(drop.project(c));
                }
                scene = scene.with(new PlotScene.Layer("block '" + w.id() + "'", PlotScene.Style.AUX, box(pts)));
            }
        }
        if (selected.isPresent()) {
            Feature f = selected.get().feature();
            List<Curve2> outline = outline(f, drop);
            if (!outline.isEmpty()) {
                scene = scene.with(
                        new PlotScene.Layer(f.entity() + " '" + f.id() + "'", PlotScene.Style.OUTLINE, outline));
            }
            scene = withToolpath(scene, drop);
            scene = scene.withLabel(drop.project(f.location()), f.id());
        }
        return scene;
    }

    /** The shown moves (rapid, feed), the path travelled up to the replay point, and the tool there. */
    private PlotScene withToolpath(PlotScene scene, ViewPlane drop) {
        Optional<Shown> sh = shown();
        if (sh.isEmpty()) {
            return scene;
        }
        List<Curve2> feeds = new ArrayList<>();
        List<Curve2> rapids = new ArrayList<>();
        drawMoves(sh.get().start(), sh.get().moves(), drop, feeds, rapids);
        ReplayPoint r = replayAt(sh.get(), (double) replay / REPLAY_STEPS);
        List<Curve2> done = new ArrayList<>();
        Vec3 at = sh.get().start();
        for (int i = 0; i <= r.moveIndex(); i++) {
            Move m = sh.get().moves().get(i);
            if (!(m instanceof Move.Rapid)) {
                done.addAll(curvesOf(at, m, drop, i == r.moveIndex() ? r.fraction() : 1));
            }
            at = m.end();
        }
        String title = scene.title() + ": " + selected.get().id()
                + (layer == 0 ? "" : ", layer " + layer + " of " + layers().size());
        PlotScene out = scene.withTitle(title)
                .with(new PlotScene.Layer("rapid", PlotScene.Style.RAPID, rapids))
                .with(new PlotScene.Layer("feed", PlotScene.Style.FEED, feeds))
                .with(new PlotScene.Layer("travelled", PlotScene.Style.FINISH, done));
        double radius = section().map(ToolpathSection::toolDiameterMm).orElse(0.0) / 2;
        Vec2 tool = drop.project(r.position());
        List<Curve2> marker = new ArrayList<>();
        if (radius > 0) {
            marker.add(Arc2.circle(tool, radius, true));
        }
        double c = Math.max(1, radius / 3);
        marker.add(Segment2.of(tool.minus(new Vec2(c, 0)), tool.plus(new Vec2(c, 0))));
        marker.add(Segment2.of(tool.minus(new Vec2(0, c)), tool.plus(new Vec2(0, c))));
        return out.with(new PlotScene.Layer("tool", PlotScene.Style.WARNING, marker));
    }

    /** The feature outline in the view plane; empty when the profile is not drawable. */
    static List<Curve2> outline(Feature f, ViewPlane drop) {
        List<Curve2> out = new ArrayList<>();
        Transform3 frame = f.placement();
        if (f.type() == Feature.FeatureType.ROUND_HOLE && f.diameterMm().isPresent()) {
            Vec2 c = drop.project(frame.translationPart());
            out.add(Arc2.circle(c, f.diameterMm().getAsDouble() / 2, true));
            return out;
        }
        if (f.profile().isEmpty()) {
            return out;
        }
        Profile p = f.profile().get();
        Transform3 t = frame.times(p.placement());
        List<Vec3> local = new ArrayList<>();
        if (p instanceof Profile.Linear lin && f.courseOfTravel().isPresent()) {
            // a planar face's removal boundary: the profile swept along the course of travel
            TravelPath c = f.courseOfTravel().get();
            Vec3 p0 = p.placement().applyToPoint(Vec3.ZERO);
            Vec3 a = p.placement().applyToDirection(Vec3.UNIT_X).times(lin.lengthMm());
            Vec3 b = c.direction()
                    .map(d -> c.placement().applyToDirection(d).normalized())
                    .orElse(Vec3.UNIT_Y)
                    .times(c.distanceMm().orElse(0));
            List<Vec3> corners = List.of(p0, p0.plus(a), p0.plus(a).plus(b), p0.plus(b), p0);
            for (int i = 0; i + 1 < corners.size(); i++) {
                addSeen(out, corners.get(i), corners.get(i + 1), frame, drop);
            }
            return out;
        }
        if (p instanceof Profile.Rectangular r) {
            double rc =
                    Math.min(Math.max(f.orthogonalRadiusMm().orElse(0), 0), Math.min(r.lengthMm(), r.widthMm()) / 2);
            // ISO 14649: the pocket's orthogonal_radius rounds the rectangle's corners
            for (Curve2 c : new org.fresa.toolpath.Profile.RoundedRectangle(Vec2.ZERO, r.lengthMm(), r.widthMm(), rc)
                    .contour(org.fresa.geom.Tolerance.DEFAULT)
                    .curves()) {
                out.addAll(placed(c, t, drop));
            }
            return out;
        } else if (p instanceof Profile.Circular c) {
            out.add(Arc2.circle(drop.project(t.translationPart()), c.diameterMm() / 2, true));
            return out;
        } else if (p instanceof Profile.Ngon g) {
            double r = g.circumscribed() ? g.diameterMm() / 2 / Math.cos(Math.PI / g.sides()) : g.diameterMm() / 2;
            // ISO 14649-10: one side parallel to x, crossing -y
            for (int i = 0; i <= g.sides(); i++) {
                double a = -Math.PI / 2 - Math.PI / g.sides() + 2 * Math.PI * i / g.sides();
                local.add(new Vec3(r * Math.cos(a), r * Math.sin(a), 0));
            }
        } else if (p instanceof Profile.General g) {
            for (Profile.Segment s : g.segments()) {
                addSeen(out, s.start(), s.end(), t, drop);
            }
            return out;
        }
        for (int i = 0; i + 1 < local.size(); i++) {
            addSeen(out, local.get(i), local.get(i + 1), t, drop);
        }
        return out;
    }

    /**
     * The straight edge from {@code a} to {@code b}, placed by {@code t} and seen along the dropped
     * axis; an edge that runs along that axis is seen as a point and drawn as nothing.
     */
    private static void addSeen(List<Curve2> out, Vec3 a, Vec3 b, Transform3 t, ViewPlane drop) {
        Vec2 u = drop.project(t.applyToPoint(a));
        Vec2 w = drop.project(t.applyToPoint(b));
        if (u.distance(w) > 0) {
            out.add(Segment2.of(u, w));
        }
    }

    /**
     * A curve of a profile's own plane placed by {@code t} and seen along the dropped axis: an
     * arc stays an arc when the plane faces the view, else it becomes chords.
     */
    private static List<Curve2> placed(Curve2 c, Transform3 t, ViewPlane drop) {
        List<Curve2> out = new ArrayList<>();
        if (c instanceof Arc2 a) {
            double along = t.zAxis().dot(drop.viewAxis());
            if (Math.abs(Math.abs(along) - 1) < 1e-9) {
                boolean keep = (along > 0) == drop.keepsSense();
                out.add(new Arc2(
                        drop.project(t.applyToPoint(Vec3.of(a.center(), 0))),
                        drop.project(t.applyToPoint(Vec3.of(a.start(), 0))),
                        drop.project(t.applyToPoint(Vec3.of(a.end(), 0))),
                        keep == a.ccw()));
                return out;
            }
            int n = 16;
            for (int i = 0; i < n; i++) {
                out.add(Segment2.of(
                        drop.project(t.applyToPoint(Vec3.of(a.pointAt((double) i / n), 0))),
                        drop.project(t.applyToPoint(Vec3.of(a.pointAt((double) (i + 1) / n), 0)))));
            }
            return out;
        }
        Vec2 u = drop.project(t.applyToPoint(Vec3.of(c.start(), 0)));
        Vec2 w = drop.project(t.applyToPoint(Vec3.of(c.end(), 0)));
        if (u.distance(w) > 0) {
            out.add(Segment2.of(u, w));
        }
        return out;
    }

    private static List<Curve2> box(List<Vec2> pts) {
        Box2 b = Box2.around(pts);
        double x0 = b.minX();
        double y0 = b.minY();
        double x1 = b.maxX();
        double y1 = b.maxY();
        return List.of(
                Segment2.of(x0, y0, x1, y0),
                Segment2.of(x1, y0, x1, y1),
                Segment2.of(x1, y1, x0, y1),
                Segment2.of(x0, y1, x0, y0));
    }

    private static String n(double d) {
        return ExactDecimal.of(Math.round(d * 1e4) / 1e4 + 0.0);
    }

    private static String v(Vec3 p) {
        return String.format(Locale.ROOT, "(%s, %s, %s)", n(p.x()), n(p.y()), n(p.z()));
    }

    /** The path conventions the tab offers, in its list's order: Fresa's, then the thesis's. */
    static final List<org.fresa.toolpath.PathConvention> PATHS =
            List.of(org.fresa.toolpath.PathConvention.FRESA, org.fresa.toolpath.PathConvention.THESIS);

    /** How the tab's list names a path convention. */
    static String pathsLabel(org.fresa.toolpath.PathConvention p) {
        return p == org.fresa.toolpath.PathConvention.THESIS ? "the 2016 robot thesis's points" : "Fresa's paths";
    }

    /**
     * The job's STEP-NC settings once this file is read in the tab: the job's own when it already
     * names the file (its post and choices kept), else the file with the default post and choices;
     * in both cases with the path conventions the tab shows.
     */
    static org.fresa.job.JobSettings.StepNcSettings settingsFor(
            org.fresa.job.Job job, java.nio.file.Path file, org.fresa.toolpath.PathConvention paths) {
        return job.stepnc()
                .filter(s -> s.file().equals(file))
                .orElseGet(() -> new org.fresa.job.JobSettings.StepNcSettings(
                        file,
                        job.stepnc()
                                .map(org.fresa.job.JobSettings.StepNcSettings::post)
                                .orElse(org.fresa.job.JobSettings.StepNcSettings.DEFAULTS.post())))
                .withPaths(paths);
    }
}
