package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.fresa.geom.Vec3;
import org.junit.jupiter.api.Test;

class OrbitCameraTest {

    static final double EPS = 1e-9;

    private static OrbitCamera fitted() {
        OrbitCamera c = new OrbitCamera();
        // a cube of side 200 about (100, 100, 100): radius = sqrt(3) * 100
        c.fit(List.of(Vec3.ZERO, new Vec3(200, 200, 200)));
        return c;
    }

    @Test
    void theCentreOfWhatWasFittedIsTheMiddleOfTheView() {
        double[] p = fitted().project(new Vec3(100, 100, 100), 400, 300);
        assertAll(
                () -> assertEquals(200, p[0], EPS),
                () -> assertEquals(150, p[1], EPS),
                () -> assertEquals(0, p[2], EPS));
    }

    @Test
    void worldZIsDrawnUpwards() {
        OrbitCamera c = fitted();
        double[] low = c.project(new Vec3(100, 100, 0), 400, 300);
        double[] high = c.project(new Vec3(100, 100, 200), 400, 300);
        assertTrue(high[1] < low[1]);
        assertEquals(low[0], high[0], EPS);
    }

    @Test
    void fromTheFrontSideOnYGoesRightAndXComesTowardsTheViewer() {
        OrbitCamera c = fitted();
        c.rotate(-OrbitCamera.DEFAULT_AZIMUTH_DEG, -OrbitCamera.DEFAULT_ELEVATION_DEG);
        // azimuth 0, elevation 0: the camera on +x looking towards -x
        double s = c.scale(400, 300);
        double[] y = c.project(new Vec3(100, 200, 100), 400, 300);
        double[] x = c.project(new Vec3(200, 100, 100), 400, 300);
        assertAll(
                () -> assertEquals(200 + 100 * s, y[0], EPS),
                () -> assertEquals(150, y[1], EPS),
                () -> assertEquals(200, x[0], EPS),
                () -> assertEquals(100, x[2], EPS));
        assertEquals(300 / (2.2 * Math.sqrt(3) * 100), s, EPS);
    }

    @Test
    void zoomAndElevationStayWithinBoundsAndHomeResets() {
        OrbitCamera c = fitted();
        c.rotate(30, 500);
        c.zoomBy(1000);
        assertAll(
                () -> assertEquals(OrbitCamera.MAX_ELEVATION_DEG, c.elevationDeg()),
                () -> assertEquals(OrbitCamera.MAX_ZOOM, c.zoom()));
        c.reset();
        assertAll(
                () -> assertEquals(OrbitCamera.DEFAULT_AZIMUTH_DEG, c.azimuthDeg()),
                () -> assertEquals(OrbitCamera.DEFAULT_ELEVATION_DEG, c.elevationDeg()),
                () -> assertEquals(1, c.zoom()));
        assertThrows(IllegalArgumentException.class, () -> c.zoomBy(0));
    }

    @Test
    void doublingTheZoomDoublesDistancesOnScreen() {
        OrbitCamera c = fitted();
        double before = c.project(new Vec3(200, 100, 100), 400, 300)[0] - 200;
        c.zoomBy(2);
        double after = c.project(new Vec3(200, 100, 100), 400, 300)[0] - 200;
        assertEquals(2 * before, after, EPS);
    }
}
