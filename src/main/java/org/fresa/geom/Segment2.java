package org.fresa.geom;

/**
 * A directed straight segment in the plane.
 *
 * @param start first point (mm)
 * @param end last point (mm); may equal start only where a caller explicitly allows it
 */
public record Segment2(Vec2 start, Vec2 end) implements Curve2 {

    public Segment2 {
        java.util.Objects.requireNonNull(start, "start");
        java.util.Objects.requireNonNull(end, "end");
    }

    public static Segment2 of(Vec2 start, Vec2 end) {
        return new Segment2(start, end);
    }

    public static Segment2 of(double x1, double y1, double x2, double y2) {
        return new Segment2(new Vec2(x1, y1), new Vec2(x2, y2));
    }

    public Vec2 direction() {
        return end.minus(start);
    }

    @Override
    public double length() {
        return start.distance(end);
    }

    @Override
    public Segment2 reversed() {
        return new Segment2(end, start);
    }

    @Override
    public Vec2 pointAt(double fraction) {
        return start.interpolate(end, fraction);
    }

    /**
     * @throws IllegalArgumentException for a zero-length segment, which has no direction
     */
    @Override
    public Vec2 startTangent() {
        return direction().normalized();
    }

    @Override
    public Vec2 endTangent() {
        return direction().normalized();
    }

    @Override
    public double areaContribution() {
        return 0.5 * start.cross(end);
    }

    @Override
    public Box2 bounds() {
        return Box2.of(start, end);
    }

    @Override
    public Segment2 translated(Vec2 by) {
        return new Segment2(start.plus(by), end.plus(by));
    }

    @Override
    public double distanceTo(Vec2 p) {
        Vec2 d = direction();
        double len2 = d.dot(d);
        if (len2 == 0) {
            return p.distance(start);
        }
        double t = Math.max(0, Math.min(1, p.minus(start).dot(d) / len2));
        return p.distance(start.plus(d.times(t)));
    }
}
