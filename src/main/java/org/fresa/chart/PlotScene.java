package org.fresa.chart;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import org.fresa.geom.Arc2;
import org.fresa.geom.Box2;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Segment2;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;

/**
 * What a 2D plot shows, independent of the drawing library: layers of plane curves (lines and
 * exact arcs) with a style each, and labels. Modules fill a scene; {@link ToolpathChart} draws it.
 *
 * @param title the plot's title (may be empty)
 * @param layers drawn in order, later over earlier
 * @param labels text at points
 * @param axes the names of the horizontal and vertical axes (the plane the scene is seen in)
 */
public record PlotScene(String title, List<Layer> layers, List<Label> labels, Axes axes) {

    /** The names of the plot's axes, with their unit: the view's plane, not always x and y. */
    public record Axes(String horizontal, String vertical) {
        /** Seen from above: x to the right, y up. */
        public static final Axes XY_MM = new Axes("x (mm)", "y (mm)");

        public Axes {
            Objects.requireNonNull(horizontal, "horizontal");
            Objects.requireNonNull(vertical, "vertical");
        }
    }

    /** How a layer is drawn. */
    public enum Style {
        /** Stock or part outline: dark, solid. */
        OUTLINE,
        /** Filled material (sheet cutting): give the outer contours and their holes in one layer, even-odd. */
        PART,
        /** A hole or island: outline only. */
        HOLE,
        /** Cutting moves at feed. */
        FEED,
        /** Finishing moves. */
        FINISH,
        /** Rapid moves: thin and dashed. */
        RAPID,
        /** Pierce points: small filled discs. */
        PIERCE,
        /** Something the planner must look at (open chains, uncut material). */
        WARNING,
        /** Construction lines, offsets, leads. */
        AUX
    }

    /** A set of curves drawn in one style. */
    public record Layer(String name, Style style, List<Curve2> curves) {
        public Layer {
            Objects.requireNonNull(name, "name");
            Objects.requireNonNull(style, "style");
            curves = List.copyOf(curves);
        }
    }

    /** A text at a point (mm). */
    public record Label(Vec2 at, String text) {}

    public PlotScene {
        Objects.requireNonNull(title, "title");
        layers = List.copyOf(layers);
        labels = List.copyOf(labels);
        Objects.requireNonNull(axes, "axes");
    }

    /** A scene seen from above (axes x and y). */
    public PlotScene(String title, List<Layer> layers, List<Label> labels) {
        this(title, layers, labels, Axes.XY_MM);
    }

    public static PlotScene empty(String title) {
        return new PlotScene(title, List.of(), List.of());
    }

    public PlotScene with(Layer layer) {
        List<Layer> l = new ArrayList<>(layers);
        l.add(layer);
        return new PlotScene(title, l, labels, axes);
    }

    public PlotScene withLabel(Vec2 at, String text) {
        List<Label> l = new ArrayList<>(labels);
        l.add(new Label(at, text));
        return new PlotScene(title, layers, l, axes);
    }

    /**
     * The scene with a ring and a cross at a point in the warning style, the place a warning of
     * the module names.
     *
     * @param radiusMm the ring's radius
     */
    public PlotScene withMarker(String name, Vec2 at, double radiusMm) {
        double r = Math.max(1e-3, radiusMm);
        return with(new Layer(
                name,
                Style.WARNING,
                List.of(
                        Arc2.circle(at, r, true),
                        Segment2.of(at.minus(new Vec2(2 * r, 0)), at.plus(new Vec2(2 * r, 0))),
                        Segment2.of(at.minus(new Vec2(0, 2 * r)), at.plus(new Vec2(0, 2 * r))))));
    }

    /** The same scene under another title. */
    public PlotScene withTitle(String newTitle) {
        return new PlotScene(newTitle, layers, labels, axes);
    }

    /** The same scene with other axis names (a front or side view). */
    public PlotScene withAxes(Axes newAxes) {
        return new PlotScene(title, layers, labels, newAxes);
    }

    public PlotScene withContour(String name, Style style, Contour c) {
        return with(new Layer(name, style, c.curves()));
    }

    /**
     * The XY projection of a toolpath: feeds, arcs (as arcs when they lie in XY planes) and rapids
     * in separate layers.
     */
    public PlotScene withToolpath(Toolpath path) {
        List<Curve2> feed = new ArrayList<>();
        List<Curve2> rapid = new ArrayList<>();
        for (ToolpathSection s : path.sections()) {
            project(s, feed, rapid);
        }
        return with(new Layer("rapid", Style.RAPID, rapid)).with(new Layer("feed", Style.FEED, feed));
    }

    /**
     * {@link #withToolpath} with the feeds of every tool after the first in a layer of their own
     * ("feed T2"), in the finishing style: a rest tool's pieces seen apart from the first tool's
     * passes.
     */
    public PlotScene withToolpathByTool(Toolpath path) {
        if (path.sections().isEmpty()) {
            return withToolpath(path);
        }
        int first = path.sections().get(0).toolNumber();
        List<Curve2> feed = new ArrayList<>();
        List<Curve2> rapid = new ArrayList<>();
        java.util.Map<Integer, List<Curve2>> others = new java.util.TreeMap<>();
        for (ToolpathSection s : path.sections()) {
            project(
                    s,
                    s.toolNumber() == first ? feed : others.computeIfAbsent(s.toolNumber(), k -> new ArrayList<>()),
                    rapid);
        }
        PlotScene scene = with(new Layer("rapid", Style.RAPID, rapid)).with(new Layer("feed", Style.FEED, feed));
        for (var e : others.entrySet()) {
            scene = scene.with(new Layer("feed T" + e.getKey(), Style.FINISH, e.getValue()));
        }
        return scene;
    }

    private static void project(ToolpathSection s, List<Curve2> feed, List<Curve2> rapid) {
        Vec3 at = s.start();
        for (Move m : s.moves()) {
            Vec2 a = at.xy();
            Vec2 b = m.end().xy();
            if (m instanceof Move.Circular c && Math.abs(Math.abs(c.normal().z()) - 1) < 1e-12) {
                boolean ccw = c.ccw() == (c.normal().z() > 0);
                feed.add(new Arc2(c.center().xy(), a, b, ccw));
            } else if (!a.equals(b)) {
                (m instanceof Move.Rapid ? rapid : feed).add(new Segment2(a, b));
            }
            at = m.end();
        }
    }

    /** The box holding every curve and label, or empty when there is nothing. */
    public java.util.Optional<Box2> bounds() {
        Box2 b = null;
        for (Layer l : layers) {
            for (Curve2 c : l.curves()) {
                b = b == null ? c.bounds() : b.union(c.bounds());
            }
        }
        for (Label l : labels) {
            b = b == null ? Box2.of(l.at(), l.at()) : b.including(l.at());
        }
        return java.util.Optional.ofNullable(b);
    }
}
