package org.fresa.ui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.Polygon;
import java.awt.RenderingHints;
import java.awt.event.ActionEvent;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import java.awt.geom.Line2D;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Objects;
import javax.swing.AbstractAction;
import javax.swing.JComponent;
import javax.swing.KeyStroke;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.fresa.kin.TrajectoryPoint;

/**
 * The robot cell in 3D (robot base frame, mm, z up), drawn with Java2D through an
 * {@link OrbitCamera}: floor grid, table top, workpiece box, the toolpath coloured by status
 * (green ok, red unreachable, orange relink), the robot as links at the replayed point with its
 * spindle and cutter, and the base, table, workpiece and tool frames. Drag or the arrow keys turn the view, the wheel or
 * +/- zoom, Home resets.
 */
final class CellView extends JComponent {

    private static final long serialVersionUID = 1L;
    static final Color OK = new Color(0, 140, 60);
    static final Color UNREACHABLE = new Color(210, 0, 0);
    static final Color RELINK = new Color(230, 130, 0);
    private static final Color SPINDLE = new Color(70, 75, 85);
    private static final Color CUTTER = new Color(150, 160, 175);
    private static final Color[] AXES = {new Color(210, 40, 40), new Color(30, 150, 50), new Color(40, 80, 220)};
    private static final double KEY_STEP_DEG = 5;
    private static final double DRAG_DEG_PER_PIXEL = 0.5;

    private final PositionViewModel vm;
    private final transient OrbitCamera camera = new OrbitCamera();
    private transient Object fittedTo;
    // the last picture drawn, of this scene with this camera, size and text
    private transient java.awt.image.BufferedImage picture;
    private transient CellScene pictureScene;
    private transient Object pictureKey;
    private int lastX;
    private int lastY;

    CellView(PositionViewModel vm) {
        this.vm = vm;
        setPreferredSize(new Dimension(640, 420));
        setName("position-cell");
        setFocusable(true);
        setToolTipText("The cell in 3D: drag or arrow keys to turn, wheel or +/- to zoom, Home to reset");
        MouseAdapter mouse = new MouseAdapter() {
            @Override
            public void mousePressed(MouseEvent e) {
                requestFocusInWindow();
                lastX = e.getX();
                lastY = e.getY();
            }

            @Override
            public void mouseDragged(MouseEvent e) {
                camera.rotate(-(e.getX() - lastX) * DRAG_DEG_PER_PIXEL, (e.getY() - lastY) * DRAG_DEG_PER_PIXEL);
                lastX = e.getX();
                lastY = e.getY();
                repaint();
            }

            @Override
            public void mouseWheelMoved(MouseWheelEvent e) {
                camera.zoomBy(Math.pow(1.1, -e.getPreciseWheelRotation()));
                repaint();
            }
        };
        addMouseListener(mouse);
        addMouseMotionListener(mouse);
        addMouseWheelListener(mouse);
        bind("LEFT", "turn-left", () -> camera.rotate(KEY_STEP_DEG, 0));
        bind("RIGHT", "turn-right", () -> camera.rotate(-KEY_STEP_DEG, 0));
        bind("UP", "turn-up", () -> camera.rotate(0, KEY_STEP_DEG));
        bind("DOWN", "turn-down", () -> camera.rotate(0, -KEY_STEP_DEG));
        bind("HOME", "reset-view", camera::reset);
        bind("PLUS", "zoom-in", () -> camera.zoomBy(1.25));
        bind("EQUALS", "zoom-in", () -> camera.zoomBy(1.25));
        bind("ADD", "zoom-in", () -> camera.zoomBy(1.25));
        bind("MINUS", "zoom-out", () -> camera.zoomBy(0.8));
        bind("SUBTRACT", "zoom-out", () -> camera.zoomBy(0.8));
    }

    /** What is drawn now (the GUI test checks the replayed robot). */
    CellScene scene() {
        return vm.scene();
    }

    /** The camera (the GUI test turns it). */
    OrbitCamera camera() {
        return camera;
    }

    private void bind(String key, String name, Runnable r) {
        getInputMap(WHEN_FOCUSED).put(KeyStroke.getKeyStroke(key), name);
        getActionMap().put(name, new AbstractAction() {
            private static final long serialVersionUID = 1L;

            @Override
            public void actionPerformed(ActionEvent e) {
                r.run();
                repaint();
            }
        });
    }

    /**
     * Copies the picture of the scene as it is now, drawn again only when the scene, the camera,
     * the size or the robot's name has changed since: every other repaint (one queued behind the
     * paint of a live answer, a tooltip, a dialog closed over the view) is a copy of one image,
     * not thousands of antialiased shapes sent one by one to the display.
     */
    @Override
    protected void paintComponent(Graphics g0) {
        CellScene sc = vm.scene();
        Object fit = vm.fitKey();
        if (!Objects.equals(fit, fittedTo)) {
            camera.fit(sc.points());
            fittedTo = fit;
        }
        int w = getWidth();
        int h = getHeight();
        Graphics2D g = (Graphics2D) g0.create();
        try {
            double scale = Math.max(1, g.getTransform().getScaleX());
            Font font = getFont() != null ? getFont() : new Font(Font.SANS_SERIF, Font.PLAIN, 12);
            java.util.List<Object> key =
                    java.util.List.of(camera.projection(w, h), vm.robot().name(), font, scale);
            if (picture == null || pictureScene != sc && !sc.equals(pictureScene) || !key.equals(pictureKey)) {
                int iw = Math.max(1, (int) Math.ceil(w * scale));
                int ih = Math.max(1, (int) Math.ceil(h * scale));
                if (picture == null || picture.getWidth() != iw || picture.getHeight() != ih) {
                    picture = new java.awt.image.BufferedImage(iw, ih, java.awt.image.BufferedImage.TYPE_INT_RGB);
                }
                Graphics2D p = picture.createGraphics();
                try {
                    p.scale(scale, scale);
                    p.setFont(font);
                    paintScene(p, sc, w, h);
                } finally {
                    p.dispose();
                }
                pictureScene = sc;
                pictureKey = key;
            }
            g.drawImage(picture, 0, 0, w, h, null);
        } finally {
            g.dispose();
        }
    }

    private void paintScene(Graphics2D g, CellScene sc, int w, int h) {
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
        g.setColor(new Color(250, 251, 253));
        g.fillRect(0, 0, w, h);

        g.setStroke(new BasicStroke(1f));
        g.setColor(new Color(222, 226, 232));
        for (List<Vec3> line : sc.floor()) {
            draw(g, line.get(0), line.get(1), w, h);
        }
        if (!sc.table().isEmpty()) {
            Polygon p = new Polygon();
            for (Vec3 v : sc.table()) {
                double[] s = camera.project(v, w, h);
                p.addPoint((int) Math.round(s[0]), (int) Math.round(s[1]));
            }
            g.setColor(new Color(205, 170, 120, 140));
            g.fillPolygon(p);
            g.setColor(new Color(140, 100, 50));
            g.drawPolygon(p);
        }
        g.setStroke(new BasicStroke(1.6f));
        g.setColor(new Color(60, 90, 160));
        for (List<Vec3> e : sc.workpiece()) {
            draw(g, e.get(0), e.get(1), w, h);
        }
        g.setStroke(new BasicStroke(1.3f));
        // one path per colour: thousands of separate line draws cost more than an event may take;
        // each run of joined segments is one polyline, and points closer than half a pixel to the
        // last one drawn are passed over (the run's end is always drawn): at the usual zoom the
        // path's points are a fraction of a pixel apart, and antialiased stroking of each of them
        // was most of the first paint of a result (54 ms on a cold event thread)
        java.util.Map<TrajectoryPoint.Status, Pen> byStatus = new java.util.EnumMap<>(TrajectoryPoint.Status.class);
        // the camera's vectors once, and each point once (a segment starts where the last ended)
        OrbitCamera.Projection view = camera.projection(w, h);
        Vec3 last = null;
        double[] lastAt = null;
        for (CellScene.PathSegment s : sc.path()) {
            Pen pen = byStatus.computeIfAbsent(s.status(), k -> new Pen());
            double[] a = s.from().equals(last) ? lastAt : view.project(s.from());
            double[] b = view.project(s.to());
            pen.segment(s.from(), a, s.to(), b);
            last = s.to();
            lastAt = b;
        }
        byStatus.forEach((status, pen) -> {
            g.setColor(colour(status));
            g.draw(pen.finish());
        });
        paintRobot(g, sc, w, h);
        List<java.awt.Rectangle> labels = new ArrayList<>();
        for (CellScene.Frame f : sc.frames()) {
            paintFrame(g, f, w, h, labels);
        }
        sc.selected().ifPresent(p -> {
            double[] s = camera.project(p.at(), w, h);
            g.setStroke(new BasicStroke(2f));
            g.setColor(colour(p.status()));
            g.drawOval((int) Math.round(s[0]) - 7, (int) Math.round(s[1]) - 7, 14, 14);
        });
        g.setFont(g.getFont().deriveFont(Font.PLAIN, 11f));
        g.setColor(new Color(90, 90, 90));
        String hint = String.format(
                java.util.Locale.ROOT,
                "%s; view az %.0f deg, el %.0f deg, zoom %.2f. Drag or arrows: turn; wheel or +/-: zoom; Home: reset",
                vm.robot().name(),
                camera.azimuthDeg(),
                camera.elevationDeg(),
                camera.zoom());
        g.drawString(hint, 8, h - 8);
        int y = 16;
        g.setColor(OK);
        g.drawString("ok", 8, y);
        g.setColor(RELINK);
        g.drawString("relink", 30, y);
        g.setColor(UNREACHABLE);
        g.drawString("unreachable", 72, y);
    }

    /** Links far from the camera first, so that nearer ones are drawn over them. */
    private void paintRobot(Graphics2D g, CellScene sc, int w, int h) {
        record Piece(Vec3 a, Vec3 b, double depth) {}
        List<Piece> pieces = new ArrayList<>();
        for (List<Vec3> line : sc.links()) {
            for (int i = 1; i < line.size(); i++) {
                Vec3 a = line.get(i - 1);
                Vec3 b = line.get(i);
                pieces.add(new Piece(a, b, camera.project(a.interpolate(b, 0.5), w, h)[2]));
            }
        }
        pieces.sort(Comparator.comparingDouble(Piece::depth));
        g.setStroke(new BasicStroke(9f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        for (Piece p : pieces) {
            g.setColor(new Color(110, 115, 125));
            draw(g, p.a(), p.b(), w, h);
        }
        g.setStroke(new BasicStroke(5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        for (Piece p : pieces) {
            g.setColor(new Color(245, 160, 40));
            draw(g, p.a(), p.b(), w, h);
        }
        sc.tool().ifPresent(t -> paintTool(g, t, w, h));
        g.setStroke(new BasicStroke(1.2f));
        for (Vec3 j : sc.joints()) {
            double[] s = camera.project(j, w, h);
            int x = (int) Math.round(s[0]);
            int y = (int) Math.round(s[1]);
            g.setColor(new Color(50, 50, 60));
            g.fillOval(x - 5, y - 5, 10, 10);
            g.setColor(Color.WHITE);
            g.drawOval(x - 5, y - 5, 10, 10);
        }
    }

    /**
     * The spindle as a thick dark body from the flange to its nose, and the cutter from the nose
     * to the tip as wide as the STEP-NC tool's diameter at this zoom (at least 3 pixels).
     */
    private void paintTool(Graphics2D g, CellScene.ToolShape t, int w, int h) {
        double pxPerMm = camera.scale(w, h);
        if (t.flange().distance(t.nose()) > 1e-6) {
            g.setStroke(
                    new BasicStroke((float) Math.max(8, 60 * pxPerMm), BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND));
            g.setColor(SPINDLE);
            draw(g, t.flange(), t.nose(), w, h);
        }
        g.setStroke(new BasicStroke(
                (float) Math.max(3, t.diameterMm() * pxPerMm), BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND));
        g.setColor(CUTTER);
        draw(g, t.nose(), t.tip(), w, h);
    }

    private void paintFrame(Graphics2D g, CellScene.Frame f, int w, int h, List<java.awt.Rectangle> labels) {
        Transform3 t = f.pose();
        Vec3 o = t.translationPart();
        Vec3[] axes = {t.xAxis(), t.yAxis(), t.zAxis()};
        g.setStroke(new BasicStroke(2.2f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        for (int i = 0; i < 3; i++) {
            g.setColor(AXES[i]);
            Vec3 tip = o.plus(axes[i].times(f.axisMm()));
            draw(g, o, tip, w, h);
            double[] s = camera.project(tip, w, h);
            g.drawString(i == 0 ? "x" : i == 1 ? "y" : "z", (int) s[0] + 3, (int) s[1] - 3);
        }
        double[] s = camera.project(o, w, h);
        // frames often share a place (table and workpiece): their names are stacked, not overprinted
        java.awt.FontMetrics fm = g.getFontMetrics();
        java.awt.Rectangle r =
                new java.awt.Rectangle((int) s[0] + 6, (int) s[1] + 4, fm.stringWidth(f.name()), fm.getHeight());
        while (labels.stream().anyMatch(r::intersects)) {
            r.translate(0, fm.getHeight());
        }
        labels.add(r);
        g.setColor(new Color(255, 255, 255, 200));
        g.fillRect(r.x - 1, r.y, r.width + 2, r.height);
        g.setColor(new Color(30, 30, 30));
        g.drawString(f.name(), r.x, r.y + fm.getAscent());
    }

    private void draw(Graphics2D g, Vec3 a, Vec3 b, int w, int h) {
        double[] p = camera.project(a, w, h);
        double[] q = camera.project(b, w, h);
        g.draw(new Line2D.Double(p[0], p[1], q[0], q[1]));
    }

    static Color colour(TrajectoryPoint.Status s) {
        return switch (s) {
            case OK -> OK;
            case UNREACHABLE -> UNREACHABLE;
            case RELINK -> RELINK;
        };
    }

    /** A polyline of one colour being built, with the points it passed over. */
    private static final class Pen {
        private static final double MIN_STEP_PX = 0.5;
        private final java.awt.geom.Path2D path = new java.awt.geom.Path2D.Double();
        private Vec3 end;
        private double keptX;
        private double keptY;
        private double[] pending;

        void segment(Vec3 from, double[] a, Vec3 to, double[] b) {
            if (end == null || !from.equals(end)) {
                flush();
                path.moveTo(a[0], a[1]);
                keptX = a[0];
                keptY = a[1];
            }
            double dx = b[0] - keptX;
            double dy = b[1] - keptY;
            if (dx * dx + dy * dy < MIN_STEP_PX * MIN_STEP_PX) {
                pending = b;
            } else {
                path.lineTo(b[0], b[1]);
                keptX = b[0];
                keptY = b[1];
                pending = null;
            }
            end = to;
        }

        private void flush() {
            if (pending != null) {
                path.lineTo(pending[0], pending[1]);
                pending = null;
            }
        }

        java.awt.geom.Path2D finish() {
            flush();
            return path;
        }
    }
}
