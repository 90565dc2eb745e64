package org.fresa.toolpath;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fresa.geom.Box2;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;
import org.fresa.stepnc.Feature;
import org.fresa.stepnc.MachiningWorkingstep;
import org.fresa.stepnc.Operation;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.stepnc.Tool;

/**
 * The toolpaths as the 2016 STEP-NC robot thesis generated them (Rea Minango, UFSC), point for
 * point, so that its point counts (Table 5.2) and its Appendix C samples can be compared with
 * ours. Every path is a list of straight moves; each point of the thesis is one move.
 *
 * <p>The conventions, as its Appendix C shows them (docs/thesis-paths.md gives the evidence):
 * <ul>
 * <li>every workingstep starts and ends at the security plane's origin (the SETUP's plane, in the
 * workpiece frame), even on the side faces, so two workingsteps meet with the point twice;
 * <li>a drilling operation is the cycle: start above the hole by the retract plane, the surface,
 * the bottom, the surface, the retract point twice;
 * <li>a milled feature is cut in layers from its face (depth 0) down to its depth, in steps of
 * the axial depth with the remainder last; each layer is entered from its first point lifted by
 * the retract plane, follows its path and lifts its last point by the retract plane; after the
 * last layer the tool goes to the first point above the face and to the security point;
 * <li>a path ends at the feature's centre when its last contour leaves material there (further
 * than the tool radius from it every way); a tool as wide as the hole has the centre as its path;
 * <li>a pocket's paths are contour-parallel whatever its strategy: rectangles (corner radii
 * ignored) counter-clockwise from the bottom-left corner of a rectangular profile, or from a
 * rectangular polyline's first corner in its order, the first one tool radius inside the outline,
 * the next ones closer by the stepover (the thesis's contour-bidirectional roughing is not known
 * well enough to be reproduced); a circle is a regular 40-gon inscribed in it (vertices 4.5 degrees off the axes),
 * offset inward flat by flat, each polygon starting at the left end of its bottom side;
 * <li>the stepover is the tool diameter less the strategy's overlap read as a length (as STEP
 * Modeler writes it, 20 % of the diameter); the radial depth is not used;
 * <li>every straight move of a layer (sides, the links between contours, the move to the
 * centre) is divided into steps of one tool diameter, the remainder last;
 * <li>a planar face is milled bidirectionally along its course of travel, the first pass tool
 * radius inside its far side.
 * </ul>
 * Moves to the security point and to points lifted by the retract plane are rapids; the others
 * are feeds (along the tool axis at the plunge feed).
 */
public final class ThesisPaths {

    /** Sides of the polygon that stands for a circle (the thesis's n = 40). */
    public static final int CIRCLE_SIDES = 40;
    /** Lengths below this are nothing (mm). */
    static final double EPS_MM = 1e-9;

    private ThesisPaths() {}

    /** What a point of the thesis's list is for: how the move to it is written. */
    enum Kind {
        RAPID,
        FEED,
        PLUNGE
    }

    /** One point of the thesis's list, in the feature frame. */
    record Point(Vec3 at, Kind kind) {}

    /** Plans every workingstep by the thesis's conventions; what they do not cover is reported. */
    public static ToolpathPlanner.Plan plan(StepNcProgram program, PlanningChoices choices) {
        Map<String, Integer> toolNumbers = new LinkedHashMap<>();
        List<ToolpathSection> sections = new ArrayList<>();
        List<ToolpathPlanner.PlannedStep> steps = new ArrayList<>();
        List<String> problems = new ArrayList<>();
        Map<Long, String> refusals = new java.util.LinkedHashMap<>();
        Map<String, Integer> feedNotes = new LinkedHashMap<>();
        int planned = 0;
        for (MachiningWorkingstep ws : program.workingsteps()) {
            String label = ws.id().isEmpty() ? "#" + ws.instanceId() : ws.id();
            try {
                CuttingData cutting = ToolpathPlanner.cuttingData(ws.operation(), choices);
                ToolpathSection s = section(ws, label, toolNumbers, cutting);
                sections.add(s);
                cutting.notes().forEach(n -> problems.add("workingstep '" + label + "': " + n));
                steps.add(new ToolpathPlanner.PlannedStep(ws.instanceId(), label, cutting.feed()));
                if (cutting.feed().inferred()) {
                    feedNotes.merge(cutting.feed().note(), 1, Integer::sum);
                }
                planned++;
            } catch (IllegalArgumentException | UnsupportedOperationException e) {
                problems.add("workingstep '" + ws.id() + "' (#" + ws.instanceId() + "): " + e.getMessage());
                refusals.put(ws.instanceId(), e.getMessage());
            }
        }
        feedNotes.forEach(
                (note, count) -> problems.add(count + (count == 1 ? " workingstep: " : " workingsteps: ") + note));
        return new ToolpathPlanner.Plan(
                new Toolpath(sections), problems, program.workingsteps().size(), planned, steps, refusals);
    }

    static ToolpathSection section(
            MachiningWorkingstep ws, String label, Map<String, Integer> toolNumbers, CuttingData cutting) {
        Feature f = ws.feature();
        Operation op = ws.operation();
        if (!op.toolpaths().isEmpty()) {
            throw new UnsupportedOperationException("the thesis's conventions do not cover a file's own toolpaths");
        }
        Tool tool = op.tool().orElseThrow(() -> new IllegalArgumentException("the operation has no tool"));
        double dia = tool.diameterMm().orElseThrow(() -> new IllegalArgumentException("the tool has no diameter"));
        if (!(dia >= ToolpathPlanner.MIN_TOOL_MM && dia <= ToolpathPlanner.MAX_LENGTH_MM)) {
            throw new IllegalArgumentException("tool diameter " + dia + " mm is outside " + ToolpathPlanner.MIN_TOOL_MM
                    + " to " + ToolpathPlanner.MAX_LENGTH_MM + " mm");
        }
        int number =
                toolNumbers.computeIfAbsent(tool.id() + "|" + tool.body() + "|" + dia, k -> toolNumbers.size() + 1);
        Vec3 security = ws.securityPlane()
                .orElseThrow(
                        () -> new IllegalArgumentException(
                                "the thesis goes to the security plane's origin between workingsteps: this workingstep has none"))
                .translationPart();
        double retract = op.retractPlaneMm().orElse(ToolpathPlanner.DEFAULT_RETRACT_MM);
        double depth = f.depthMm().orElseThrow(() -> new IllegalArgumentException("the feature has no depth"));
        if (!(depth >= 0
                && depth <= ToolpathPlanner.MAX_LENGTH_MM
                && Math.abs(retract) <= ToolpathPlanner.MAX_LENGTH_MM)) {
            throw new IllegalArgumentException("depth " + depth + " mm or retract plane " + retract
                    + " mm is outside 0 to " + ToolpathPlanner.MAX_LENGTH_MM + " mm");
        }
        Transform3 place = f.placement();
        List<Point> local;
        if (op.type().isDrillingType()) {
            if (f.type() != Feature.FeatureType.ROUND_HOLE) {
                throw new UnsupportedOperationException("the thesis drills round holes only, not a " + f.entity());
            }
            local = drilling(op.cuttingDepthMm().orElse(depth), retract);
        } else if (op.type().isMilling()) {
            double stepover = stepover(op, dia);
            List<Vec2> path;
            switch (f.type()) {
                case ROUND_HOLE ->
                    path = circleContours(
                            f.diameterMm().orElseThrow(() -> new IllegalArgumentException("the hole has no diameter"))
                                    / 2,
                            dia,
                            stepover);
                case CLOSED_POCKET -> {
                    org.fresa.stepnc.Profile sp = f.profile()
                            .orElseThrow(() -> new IllegalArgumentException("the pocket has no boundary profile"));
                    Transform3 pp = sp.placement();
                    // STEP Modeler writes the feature's own placement (workpiece frame) as the profile's
                    if (pp.eq(f.placement(), org.fresa.geom.Tolerance.DEFAULT)) {
                        pp = Transform3.IDENTITY;
                    }
                    place = place.times(pp);
                    if (sp instanceof org.fresa.stepnc.Profile.Rectangular r) {
                        path = rectangleContours(r.lengthMm() / 2, r.widthMm() / 2, dia, stepover);
                    } else if (sp instanceof org.fresa.stepnc.Profile.General g) {
                        path = polylineRectangleContours(g, dia, stepover);
                    } else {
                        throw new UnsupportedOperationException("the thesis's conventions are known for rectangular"
                                + " pockets only, not a " + sp.entity());
                    }
                }
                case PLANAR_FACE -> {
                    Box2 box = ToolpathPlanner.faceBoundary(f);
                    Vec3 course = f.courseOfTravel()
                            .flatMap(c -> c.direction().map(d -> c.placement().applyToDirection(d)))
                            .orElse(Vec3.UNIT_X);
                    path = facePasses(box, Math.abs(course.y()) > Math.abs(course.x()), dia, stepover);
                }
                default ->
                    throw new UnsupportedOperationException("the thesis's conventions do not cover a " + f.entity());
            }
            double axial = op.axialCuttingDepthMm().orElse(depth);
            local = milled(path, layers(depth, axial), retract);
        } else {
            throw new UnsupportedOperationException("the thesis's conventions do not cover " + op.entity());
        }
        double feed = cutting.feed().feedMmPerMin();
        double plunge = op.type().isDrillingType() ? feed : feed / 2;
        List<Move> moves = new ArrayList<>();
        for (Point p : local) {
            Vec3 at = place.applyToPoint(p.at());
            moves.add(
                    switch (p.kind()) {
                        case RAPID -> new Move.Rapid(at);
                        case FEED -> new Move.Linear(at, feed);
                        case PLUNGE -> new Move.Linear(at, plunge);
                    });
        }
        moves.add(new Move.Rapid(security));
        Vec3 axis = place.applyToDirection(Vec3.UNIT_Z).normalized();
        return new ToolpathSection(label, axis, dia, number, cutting.spindleRpm(), security, moves);
    }

    /** The thesis's stepover: the diameter less the overlap read as a length. */
    static double stepover(Operation op, double diameterMm) {
        double overlap = op.strategy()
                .flatMap(s -> s.overlap().isPresent() ? Optional.of(s.overlap().getAsDouble()) : Optional.empty())
                .orElse(0.0);
        double d = diameterMm - overlap;
        if (!(d > EPS_MM)) {
            throw new IllegalArgumentException("an overlap of " + overlap + " mm read as a length leaves no stepover"
                    + " for a " + diameterMm + " mm tool");
        }
        return d;
    }

    /** The drilling cycle, in the hole's frame. */
    static List<Point> drilling(double depthMm, double retractMm) {
        Vec3 above = new Vec3(0, 0, retractMm);
        return List.of(
                new Point(above, Kind.RAPID),
                new Point(Vec3.ZERO, Kind.PLUNGE),
                new Point(new Vec3(0, 0, -depthMm), Kind.PLUNGE),
                new Point(Vec3.ZERO, Kind.PLUNGE),
                new Point(above, Kind.RAPID),
                new Point(above, Kind.RAPID));
    }

    /** The layer depths: the face (0), then every axial depth, the remainder last. */
    static List<Double> layers(double depthMm, double axialMm) {
        List<Double> out = new ArrayList<>();
        out.add(0.0);
        if (depthMm <= EPS_MM) {
            return out;
        }
        double a = axialMm > EPS_MM ? axialMm : depthMm;
        ToolpathPlanner.bounded("depth", depthMm, "axial cutting depth", a);
        for (int k = 1; k * a < depthMm - EPS_MM; k++) {
            out.add(k * a);
        }
        out.add(depthMm);
        return out;
    }

    /**
     * A milled feature's points: at every layer its path, entered from its first point lifted by
     * the retract plane and left by lifting its last point as much; then its first point above
     * the face.
     */
    static List<Point> milled(List<Vec2> path, List<Double> layers, double retractMm) {
        Vec2 first = path.get(0);
        Vec2 last = path.get(path.size() - 1);
        List<Point> out = new ArrayList<>();
        for (double layer : layers) {
            double z = -layer;
            out.add(new Point(at(first, z + retractMm), Kind.RAPID));
            for (int i = 0; i < path.size(); i++) {
                out.add(new Point(at(path.get(i), z), i == 0 ? Kind.PLUNGE : Kind.FEED));
            }
            out.add(new Point(at(last, z + retractMm), Kind.RAPID));
        }
        out.add(new Point(at(first, retractMm), Kind.RAPID));
        return out;
    }

    private static Vec3 at(Vec2 p, double z) {
        return new Vec3(p.x(), p.y(), z);
    }

    /** The points after a up to b in steps of stepMm, the remainder last; none when a = b. */
    static List<Vec2> divide(Vec2 a, Vec2 b, double stepMm) {
        Vec2 d = b.minus(a);
        double len = d.norm();
        List<Vec2> out = new ArrayList<>();
        if (len <= EPS_MM) {
            return out;
        }
        ToolpathPlanner.bounded("a side", len, "the tool diameter", stepMm);
        for (int k = 1; k * stepMm < len - EPS_MM; k++) {
            out.add(a.plus(d.times(k * stepMm / len)));
        }
        out.add(b);
        return out;
    }

    /** The corners of a rectangle about its centre, counter-clockwise from the bottom-left. */
    static final List<Vec2> BOTTOM_LEFT_CCW =
            List.of(new Vec2(-1, -1), new Vec2(1, -1), new Vec2(1, 1), new Vec2(-1, 1));

    /**
     * Contour-parallel rectangles about the origin, counter-clockwise from the bottom-left
     * corner, while both half-sizes stay at or above zero (a zero one is a line there and back).
     */
    static List<Vec2> rectangleContours(double halfXMm, double halfYMm, double diameterMm, double stepoverMm) {
        return rectangleContours(Vec2.ZERO, halfXMm, halfYMm, BOTTOM_LEFT_CCW, diameterMm, stepoverMm);
    }

    /**
     * A pocket whose outline is a closed polyline of four sides along the axes (the original ISO
     * 14649-11 example 1's): its rectangles start at the corner of the polyline's first point and
     * run in the polyline's order.
     */
    static List<Vec2> polylineRectangleContours(
            org.fresa.stepnc.Profile.General g, double diameterMm, double stepoverMm) {
        List<Vec2> corners = new ArrayList<>();
        for (org.fresa.stepnc.Profile.Segment seg : g.segments()) {
            if (!(seg instanceof org.fresa.stepnc.Profile.Line line)) {
                throw new UnsupportedOperationException(
                        "the thesis's conventions are known for straight outlines only");
            }
            corners.add(new Vec2(line.start().x(), line.start().y()));
        }
        Box2 box = Box2.around(corners);
        Vec2 centre = new Vec2((box.minX() + box.maxX()) / 2, (box.minY() + box.maxY()) / 2);
        List<Vec2> signs = new ArrayList<>();
        for (Vec2 c : corners) {
            double sx = Math.signum(c.x() - centre.x());
            double sy = Math.signum(c.y() - centre.y());
            if (Math.abs(Math.abs(c.x() - centre.x()) - box.width() / 2) > 1e-6
                    || Math.abs(Math.abs(c.y() - centre.y()) - box.height() / 2) > 1e-6) {
                throw new UnsupportedOperationException(
                        "the thesis's conventions are known for rectangular outlines" + " only");
            }
            signs.add(new Vec2(sx, sy));
        }
        if (!g.closed() || signs.size() != 4) {
            throw new UnsupportedOperationException(
                    "the thesis's conventions are known for closed rectangular" + " outlines only");
        }
        return rectangleContours(centre, box.width() / 2, box.height() / 2, signs, diameterMm, stepoverMm);
    }

    /**
     * Contour-parallel rectangles about a centre, each through the given corners in order (signs
     * of the half-sizes) and back, while both half-sizes stay at or above zero.
     */
    static List<Vec2> rectangleContours(
            Vec2 centre, double halfXMm, double halfYMm, List<Vec2> cornerSigns, double diameterMm, double stepoverMm) {
        List<Vec2> out = new ArrayList<>();
        double ax = halfXMm - diameterMm / 2;
        double ay = halfYMm - diameterMm / 2;
        ToolpathPlanner.bounded("the pocket", Math.max(ax, ay), "the stepover", stepoverMm);
        double lastX = -1;
        double lastY = -1;
        while (ax >= -EPS_MM && ay >= -EPS_MM) {
            double x = Math.max(ax, 0);
            double y = Math.max(ay, 0);
            List<Vec2> corners = new ArrayList<>();
            for (Vec2 sign : cornerSigns) {
                corners.add(centre.plus(new Vec2(sign.x() * x, sign.y() * y)));
            }
            corners.add(corners.get(0));
            link(out, corners, diameterMm);
            lastX = x;
            lastY = y;
            ax -= stepoverMm;
            ay -= stepoverMm;
        }
        return toCentre(out, Math.min(lastX, lastY) > diameterMm / 2 + EPS_MM, centre, diameterMm);
    }

    /**
     * The path ended at the centre when the last contour leaves material there (it is further
     * than the tool radius from the centre every way), or the centre alone when there is no
     * contour (a tool as wide as the feature).
     */
    private static List<Vec2> toCentre(List<Vec2> path, boolean uncut, Vec2 centre, double stepMm) {
        if (path.isEmpty()) {
            path.add(centre);
        } else if (uncut) {
            path.addAll(divide(path.get(path.size() - 1), centre, stepMm));
        }
        return path;
    }

    /**
     * Contour-parallel 40-gons in a circle about the origin: the first inscribed in the circle
     * and offset inward by the tool radius flat by flat, the next ones closer by the stepover;
     * none when the tool fills the circle.
     */
    static List<Vec2> circleContours(double radiusMm, double diameterMm, double stepoverMm) {
        List<Vec2> out = new ArrayList<>();
        double half = Math.PI / CIRCLE_SIDES;
        double apothem = radiusMm * Math.cos(half) - diameterMm / 2;
        ToolpathPlanner.bounded("the hole", Math.max(apothem, 0), "the stepover", stepoverMm);
        double start = 1.5 * Math.PI - half;
        double lastApothem = -1;
        while (apothem > EPS_MM) {
            lastApothem = apothem;
            double r = apothem / Math.cos(half);
            List<Vec2> vertices = new ArrayList<>();
            for (int k = 0; k <= CIRCLE_SIDES; k++) {
                double t = start + 2 * half * k;
                vertices.add(new Vec2(r * Math.cos(t), r * Math.sin(t)));
            }
            link(out, vertices, diameterMm);
            apothem -= stepoverMm;
        }
        return toCentre(out, lastApothem > diameterMm / 2 + EPS_MM, Vec2.ZERO, diameterMm);
    }

    /** Appends a closed contour: linked from the path's last point, its sides divided. */
    private static void link(List<Vec2> out, List<Vec2> contour, double stepMm) {
        if (out.isEmpty()) {
            out.add(contour.get(0));
        } else {
            out.addAll(divide(out.get(out.size() - 1), contour.get(0), stepMm));
        }
        for (int i = 0; i + 1 < contour.size(); i++) {
            out.addAll(divide(contour.get(i), contour.get(i + 1), stepMm));
        }
    }

    /**
     * Bidirectional passes over a face's box: along y when alongY (else x), the first pass tool
     * radius inside the far side, the others closer by the stepover, the last tool radius inside
     * the near side; each pass runs tool radius inside the box's ends.
     */
    static List<Vec2> facePasses(Box2 box, boolean alongY, double diameterMm, double stepoverMm) {
        double r = diameterMm / 2;
        double crossHi = (alongY ? box.maxX() : box.maxY()) - r;
        double crossLo = (alongY ? box.minX() : box.minY()) + r;
        double lo = (alongY ? box.minY() : box.minX()) + r;
        double hi = (alongY ? box.maxY() : box.maxX()) - r;
        List<Double> cross = new ArrayList<>();
        cross.add(crossHi);
        for (Vec2 p : divide(new Vec2(crossHi, 0), new Vec2(Math.min(crossLo, crossHi), 0), stepoverMm)) {
            cross.add(p.x());
        }
        List<Vec2> out = new ArrayList<>();
        boolean forward = true;
        for (double c : cross) {
            Vec2 a = alongY ? new Vec2(c, forward ? lo : hi) : new Vec2(forward ? lo : hi, c);
            Vec2 b = alongY ? new Vec2(c, forward ? hi : lo) : new Vec2(forward ? hi : lo, c);
            if (out.isEmpty()) {
                out.add(a);
            } else {
                out.addAll(divide(out.get(out.size() - 1), a, diameterMm));
            }
            out.addAll(divide(a, b, diameterMm));
            forward = !forward;
        }
        return out;
    }
}
