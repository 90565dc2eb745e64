package org.fresa.ui;

import java.util.List;
import org.fresa.geom.Vec3;

/**
 * An orthographic orbit camera for the 3D cell view, without Swing: it looks at the centre of
 * what it was fitted to from the direction given by an azimuth (about the world z axis, from +x
 * towards +y) and an elevation (above the xy plane), and maps world points (mm) to pixels.
 *
 * <pre>
 * d     = (cos el cos az, cos el sin az, sin el)     from the centre towards the camera
 * right = (-sin az, cos az, 0)
 * up    = d x right
 * screen x = width/2  + s (p - c) . right
 * screen y = height/2 - s (p - c) . up
 * depth    = (p - c) . d                             larger is nearer the camera
 * </pre>
 *
 * with s = zoom * min(width, height) / (2.2 radius), so at zoom 1 a sphere of the fitted radius
 * fills the smaller side of the view with a margin. World z is always drawn upwards.
 */
final class OrbitCamera {

    static final double DEFAULT_AZIMUTH_DEG = -60;
    static final double DEFAULT_ELEVATION_DEG = 25;
    static final double MIN_ZOOM = 0.2;
    static final double MAX_ZOOM = 20;
    static final double MAX_ELEVATION_DEG = 89;

    private double azimuthDeg = DEFAULT_AZIMUTH_DEG;
    private double elevationDeg = DEFAULT_ELEVATION_DEG;
    private double zoom = 1;
    private Vec3 centre = Vec3.ZERO;
    private double radiusMm = 1000;

    double azimuthDeg() {
        return azimuthDeg;
    }

    double elevationDeg() {
        return elevationDeg;
    }

    double zoom() {
        return zoom;
    }

    /** Looks at the centre of the points' bounding box, sized to hold them all. */
    void fit(List<Vec3> points) {
        if (points.isEmpty()) {
            centre = Vec3.ZERO;
            radiusMm = 1000;
            return;
        }
        double[] lo = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE};
        double[] hi = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        for (Vec3 p : points) {
            double[] v = {p.x(), p.y(), p.z()};
            for (int i = 0; i < 3; i++) {
                lo[i] = Math.min(lo[i], v[i]);
                hi[i] = Math.max(hi[i], v[i]);
            }
        }
        centre = new Vec3((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
        radiusMm = Math.max(50, new Vec3(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]).norm() / 2);
    }

    /** Turns the view: azimuth by dAz, elevation by dEl (deg), elevation kept within +-89 deg. */
    void rotate(double dAzDeg, double dElDeg) {
        azimuthDeg = Math.IEEEremainder(azimuthDeg + dAzDeg, 360);
        elevationDeg = Math.max(-MAX_ELEVATION_DEG, Math.min(MAX_ELEVATION_DEG, elevationDeg + dElDeg));
    }

    /** Multiplies the zoom, kept within 0.2 .. 20. */
    void zoomBy(double factor) {
        if (!(factor > 0) || !Double.isFinite(factor)) {
            throw new IllegalArgumentException("zoom factor must be positive: " + factor);
        }
        zoom = Math.max(MIN_ZOOM, Math.min(MAX_ZOOM, zoom * factor));
    }

    /** Back to the default direction and zoom (the fitted centre stays). */
    void reset() {
        azimuthDeg = DEFAULT_AZIMUTH_DEG;
        elevationDeg = DEFAULT_ELEVATION_DEG;
        zoom = 1;
    }

    /** The unit vector from the centre towards the camera. */
    Vec3 towardsCamera() {
        double az = Math.toRadians(azimuthDeg);
        double el = Math.toRadians(elevationDeg);
        return new Vec3(Math.cos(el) * Math.cos(az), Math.cos(el) * Math.sin(az), Math.sin(el));
    }

    /** Pixels per mm in a view of that size. */
    double scale(int width, int height) {
        return zoom * Math.max(1, Math.min(width, height)) / (2.2 * radiusMm);
    }

    /** The point on screen: {x, y, depth} (pixels, pixels, mm; larger depth is nearer). */
    double[] project(Vec3 p, int width, int height) {
        return projection(width, height).project(p);
    }

    /**
     * The projection of the camera as it is now onto a view of the given size, its vectors
     * computed once: the 3D view projects thousands of points per paint.
     */
    Projection projection(int width, int height) {
        double az = Math.toRadians(azimuthDeg);
        Vec3 d = towardsCamera();
        Vec3 right = new Vec3(-Math.sin(az), Math.cos(az), 0);
        return new Projection(centre, right, d.cross(right), d, scale(width, height), width, height);
    }

    /** A fixed projection: {@link #project} gives what the camera's {@link OrbitCamera#project} gives. */
    record Projection(Vec3 centre, Vec3 right, Vec3 up, Vec3 d, double s, int width, int height) {
        /** The point's view coordinates: x right and y down in pixels, then its depth towards the camera. */
        double[] project(Vec3 p) {
            Vec3 rel = p.minus(centre);
            return new double[] {width / 2.0 + s * rel.dot(right), height / 2.0 - s * rel.dot(up), rel.dot(d)};
        }
    }
}
