package org.fresa.toolpath;

import java.util.ArrayList;
import java.util.List;
import org.fresa.geom.Contour;
import org.fresa.geom.Curve2;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.ArcGeometry;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.operation.union.UnaryUnionOp;

/**
 * Test geometry with JTS: the area a flat cutter sweeps in the feature plane, and the pocket
 * polygon, both with arcs densified finely (0.002 mm chords), so areas compare to ~0.01 mm^2.
 */
public final class Swept {
    static final GeometryFactory GF = new GeometryFactory();
    static final double CHORD = 0.002;
    public static final int QUADRANT_SEGMENTS = 64;

    private Swept() {}

    /** Polygon of a contour. */
    public static Geometry polygon(Contour c) {
        List<Coordinate> pts = new ArrayList<>();
        for (Curve2 cu : c.curves()) {
            for (Vec2 p : densify(cu)) {
                pts.add(new Coordinate(p.x(), p.y()));
            }
        }
        pts.add(pts.get(0));
        return GF.createPolygon(pts.toArray(new Coordinate[0]));
    }

    private static List<Vec2> densify(Curve2 c) {
        List<Vec2> out = new ArrayList<>();
        out.add(c.start());
        if (c instanceof org.fresa.geom.Arc2 a && a.radius() > 0) {
            int n = Math.max(4, (int) Math.ceil(a.length() / 0.05));
            for (int k = 1; k < n; k++) {
                out.add(a.pointAt((double) k / n));
            }
        }
        return out;
    }

    /**
     * The region swept by the cutter's disc over the cutting moves whose both ends lie at or
     * below zMax (the XY shadow of the tool).
     */
    public static Geometry sweep(ToolpathSection s, double radius, double zMax) {
        List<Geometry> parts = new ArrayList<>();
        Vec3 at = s.start();
        for (Move m : s.moves()) {
            if (!(m instanceof Move.Rapid) && at.z() <= zMax + 1e-9 && m.end().z() <= zMax + 1e-9) {
                List<Coordinate> pts = new ArrayList<>();
                pts.add(new Coordinate(at.x(), at.y()));
                if (m instanceof Move.Circular c) {
                    for (Vec3 p : ArcGeometry.of(at, c).points(CHORD)) {
                        pts.add(new Coordinate(p.x(), p.y()));
                    }
                } else {
                    pts.add(new Coordinate(m.end().x(), m.end().y()));
                }
                Geometry g = pts.size() == 2 && pts.get(0).equals2D(pts.get(1))
                        ? GF.createPoint(pts.get(0))
                        : GF.createLineString(pts.toArray(new Coordinate[0]));
                parts.add(g.buffer(radius, QUADRANT_SEGMENTS));
            }
            at = m.end();
        }
        return parts.isEmpty() ? GF.createPolygon() : UnaryUnionOp.union(parts);
    }

    /** What the cutter cannot reach in any case: the pocket minus its opening by the radius. */
    public static Geometry cornerResidue(Geometry pocket, double radius) {
        return pocket.difference(pocket.buffer(-radius, QUADRANT_SEGMENTS).buffer(radius, QUADRANT_SEGMENTS));
    }

    /** The pocket area left uncut beyond the unavoidable corner residue (mm^2). */
    public static double uncutBeyondResidue(Geometry pocket, Geometry swept, double radius) {
        Geometry left = pocket.difference(swept);
        return left.difference(cornerResidue(pocket, radius).buffer(0.01)).getArea();
    }

    /** The swept area outside the pocket (mm^2): a gouge. */
    public static double gouge(Geometry pocket, Geometry swept) {
        return swept.difference(pocket.buffer(0.01)).getArea();
    }
}
