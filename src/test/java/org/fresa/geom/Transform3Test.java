package org.fresa.geom;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

class Transform3Test {

    @Test
    void rpyComposesRzRyRx() {
        Transform3 t = Transform3.ofXyzRpyDeg(1, 2, 3, 0, 0, 90);
        Vec3 p = t.applyToPoint(Vec3.UNIT_X);
        assertAll(() -> assertEquals(1, p.x(), 0), () -> assertEquals(3, p.y(), 0), () -> assertEquals(3, p.z(), 0));
    }

    @Test
    void quarterTurnsAreExact() {
        Transform3 t = Transform3.rotX(-90);
        assertEquals(Vec3.of(0, 0, -1), t.applyToDirection(Vec3.UNIT_Y));
    }

    @Test
    void inverseUndoesTheTransform() {
        Random rnd = new Random(7);
        for (int i = 0; i < 100; i++) {
            Transform3 t = Transform3.ofXyzRpyDeg(
                    rnd.nextDouble() * 1000,
                    rnd.nextDouble() * 1000,
                    rnd.nextDouble(),
                    rnd.nextDouble() * 360,
                    rnd.nextDouble() * 180 - 90,
                    rnd.nextDouble() * 360);
            Vec3 p = Vec3.of(rnd.nextDouble(), rnd.nextDouble(), rnd.nextDouble());
            assertTrue(t.inverse().applyToPoint(t.applyToPoint(p)).distance(p) < 1e-12);
            assertTrue(t.times(t.inverse()).rotationAngleTo(Transform3.IDENTITY) < 1e-14);
        }
    }

    @Test
    void rotationAngleIsAccurateNearZero() {
        Transform3 a = Transform3.rotZ(0);
        Transform3 b = Transform3.rotZ(Math.toDegrees(1e-10));
        assertEquals(1e-10, a.rotationAngleTo(b), 1e-18);
    }

    @Test
    void frameFromAxisAndReference() {
        Transform3 f = Transform3.ofFrame(Vec3.of(0, 0, 5), Vec3.of(0, -1, 0), Vec3.UNIT_X);
        assertAll(
                () -> assertTrue(Vec3.UNIT_X.eq(f.xAxis(), Tolerance.DEFAULT)),
                () -> assertTrue(Vec3.of(0, -1, 0).eq(f.zAxis(), Tolerance.DEFAULT)),
                () -> assertTrue(Vec3.of(0, 0, 1).eq(f.yAxis(), Tolerance.DEFAULT)));
    }
}
