package org.fresa.ui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.util.List;
import javax.swing.JComponent;
import org.fresa.geom.Vec3;
import org.fresa.kin.TrajectoryPoint;

/**
 * The robot cell in two projections side by side: from above (X right, Y up) and from the side
 * (X right, Z up), same scale, robot base frame in mm. Points green ok, red unreachable, orange
 * relink; the robot drawn as links at the selected point.
 */
final class CellView extends JComponent {

    private static final long serialVersionUID = 1L;
    static final Color OK = new Color(0, 140, 60);
    static final Color UNREACHABLE = new Color(210, 0, 0);
    static final Color RELINK = new Color(230, 130, 0);

    private final PositionViewModel vm;

    CellView(PositionViewModel vm) {
        this.vm = vm;
        setPreferredSize(new Dimension(700, 320));
        setName("position-cell");
        setToolTipText("The cell from above (left) and from the side (right); base frame in mm");
    }

    @Override
    protected void paintComponent(Graphics g0) {
        Graphics2D g = (Graphics2D) g0.create();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, getWidth(), getHeight());
        List<PositionViewModel.CellPoint> pts = vm.cellPoints();
        List<List<Vec3>> links = vm.robotLinks();
        // one scale for both views, fitted to everything drawn
        double minX = 0, maxX = 0, minY = 0, maxY = 0, minZ = 0, maxZ = 0;
        java.util.List<Vec3> all = new java.util.ArrayList<>();
        all.add(Vec3.ZERO);
        all.add(vm.tableOrigin());
        all.add(vm.pieceOrigin());
        pts.forEach(p -> all.add(p.at()));
        links.forEach(all::addAll);
        for (Vec3 v : all) {
            minX = Math.min(minX, v.x());
            maxX = Math.max(maxX, v.x());
            minY = Math.min(minY, v.y());
            maxY = Math.max(maxY, v.y());
            minZ = Math.min(minZ, v.z());
            maxZ = Math.max(maxZ, v.z());
        }
        double pad = 80;
        minX -= pad;
        maxX += pad;
        minY -= pad;
        maxY += pad;
        minZ -= pad;
        maxZ += pad;
        int half = getWidth() / 2;
        int h = getHeight() - 24;
        double s = Math.min(Math.min((half - 20) / (maxX - minX), (h - 20) / (maxY - minY)),
                Math.min((half - 20) / (maxX - minX), (h - 20) / (maxZ - minZ)));
        View top = new View(10, 20, s, minX, maxY, false);
        View side = new View(half + 10, 20, s, minX, maxZ, true);
        g.setColor(Color.DARK_GRAY);
        g.drawString("From above (X right, Y up)", 10, 14);
        g.drawString("From the side (X right, Z up)", half + 10, 14);
        g.setColor(Color.LIGHT_GRAY);
        g.drawLine(half, 0, half, getHeight());
        for (View v : List.of(top, side)) {
            // base, table and workpiece origins
            g.setColor(Color.BLACK);
            int[] b = v.at(Vec3.ZERO);
            g.fillRect(b[0] - 6, b[1] - 6, 12, 12);
            g.drawString("base", b[0] + 8, b[1] + 14);
            int[] t = v.at(vm.tableOrigin());
            g.setColor(new Color(120, 90, 40));
            g.drawRect(t[0] - 5, t[1] - 5, 10, 10);
            g.drawString("table", t[0] + 8, t[1] - 6);
            int[] pc = v.at(vm.pieceOrigin());
            g.setColor(new Color(40, 70, 160));
            g.drawOval(pc[0] - 4, pc[1] - 4, 8, 8);
            for (PositionViewModel.CellPoint p : pts) {
                g.setColor(colour(p.status()));
                int[] xy = v.at(p.at());
                g.fillRect(xy[0] - 1, xy[1] - 1, 3, 3);
            }
            g.setStroke(new BasicStroke(4f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
            g.setColor(new Color(90, 90, 90, 200));
            for (List<Vec3> line : links) {
                for (int i = 1; i < line.size(); i++) {
                    int[] a = v.at(line.get(i - 1));
                    int[] c = v.at(line.get(i));
                    g.drawLine(a[0], a[1], c[0], c[1]);
                }
            }
            g.setStroke(new BasicStroke(2f));
            if (!pts.isEmpty()) {
                // the replayed point, also when the robot cannot reach it
                PositionViewModel.CellPoint sel = pts.get(vm.selected());
                int[] xy = v.at(sel.at());
                g.setColor(colour(sel.status()));
                g.drawOval(xy[0] - 7, xy[1] - 7, 14, 14);
            }
            g.setStroke(new BasicStroke(1f));
            g.setColor(Color.BLACK);
            for (List<Vec3> line : links) {
                for (Vec3 joint : line) {
                    int[] a = v.at(joint);
                    g.fillOval(a[0] - 3, a[1] - 3, 6, 6);
                }
            }
        }
        int y = getHeight() - 6;
        legend(g, 10, y, OK, "ok");
        legend(g, 60, y, UNREACHABLE, "unreachable");
        legend(g, 160, y, RELINK, "relink");
        g.setColor(Color.DARK_GRAY);
        g.drawString(String.format(java.util.Locale.ROOT, "scale 1 px = %.1f mm", 1 / s), 240, y);
        g.dispose();
    }

    private static void legend(Graphics2D g, int x, int y, Color c, String text) {
        g.setColor(c);
        g.fillRect(x, y - 8, 8, 8);
        g.setColor(Color.DARK_GRAY);
        g.drawString(text, x + 11, y);
    }

    static Color colour(TrajectoryPoint.Status s) {
        return switch (s) {
            case OK -> OK;
            case UNREACHABLE -> UNREACHABLE;
            case RELINK -> RELINK;
        };
    }

    /** A projection: x to the right, y (top view) or z (side view) up. */
    private record View(int left, int top, double scale, double minX, double maxUp, boolean side) {
        int[] at(Vec3 p) {
            double up = side ? p.z() : p.y();
            return new int[] {left + (int) Math.round((p.x() - minX) * scale),
                top + (int) Math.round((maxUp - up) * scale)};
        }
    }
}
