package org.fresa.geom;

/**
 * An axis-aligned rectangle (mm), min corner inclusive of max corner.
 *
 * @param minX smallest x
 * @param minY smallest y
 * @param maxX largest x, >= minX
 * @param maxY largest y, >= minY
 */
public record Box2(double minX, double minY, double maxX, double maxY) {

    public Box2 {
        Checks.finite(minX, "minX");
        Checks.finite(minY, "minY");
        Checks.finite(maxX, "maxX");
        Checks.finite(maxY, "maxY");
        if (maxX < minX || maxY < minY) {
            throw new IllegalArgumentException("box max below min: " + minX + "," + minY + " " + maxX + "," + maxY);
        }
    }

    public static Box2 of(Vec2 a, Vec2 b) {
        return new Box2(Math.min(a.x(), b.x()), Math.min(a.y(), b.y()), Math.max(a.x(), b.x()), Math.max(a.y(), b.y()));
    }

    /** The smallest box that holds every point; there must be at least one. */
    public static Box2 around(Iterable<Vec2> points) {
        double x0 = Double.POSITIVE_INFINITY;
        double y0 = Double.POSITIVE_INFINITY;
        double x1 = Double.NEGATIVE_INFINITY;
        double y1 = Double.NEGATIVE_INFINITY;
        for (Vec2 p : points) {
            x0 = Math.min(x0, p.x());
            y0 = Math.min(y0, p.y());
            x1 = Math.max(x1, p.x());
            y1 = Math.max(y1, p.y());
        }
        return new Box2(x0, y0, x1, y1);
    }

    public Box2 including(Vec2 p) {
        return new Box2(Math.min(minX, p.x()), Math.min(minY, p.y()), Math.max(maxX, p.x()), Math.max(maxY, p.y()));
    }

    public Box2 union(Box2 o) {
        return new Box2(Math.min(minX, o.minX), Math.min(minY, o.minY), Math.max(maxX, o.maxX), Math.max(maxY, o.maxY));
    }

    public double width() {
        return maxX - minX;
    }

    public double height() {
        return maxY - minY;
    }

    public Vec2 center() {
        return new Vec2((minX + maxX) / 2, (minY + maxY) / 2);
    }

    public boolean contains(Vec2 p) {
        return p.x() >= minX && p.x() <= maxX && p.y() >= minY && p.y() <= maxY;
    }

    public boolean intersects(Box2 o) {
        return o.minX <= maxX && o.maxX >= minX && o.minY <= maxY && o.maxY >= minY;
    }
}
