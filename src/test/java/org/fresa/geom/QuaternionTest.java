package org.fresa.geom;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

class QuaternionTest {

    @Test
    void quaternionAndEulerAnglesGiveBackTheRotation() {
        Random rnd = new Random(3);
        for (int i = 0; i < 1000; i++) {
            Transform3 t = Transform3.ofXyzRpyDeg(
                    0, 0, 0, rnd.nextDouble() * 360 - 180, rnd.nextDouble() * 180 - 90, rnd.nextDouble() * 360 - 180);
            Quaternion q = Quaternion.of(t);
            assertEquals(1, Math.sqrt(q.w() * q.w() + q.x() * q.x() + q.y() * q.y() + q.z() * q.z()), 1e-15);
            assertTrue(q.w() >= 0);
            assertTrue(q.toTransform().rotationAngleTo(t) < 1e-14);
            Vec3 abc = t.zyxAnglesDeg();
            assertTrue(
                    Transform3.ofXyzRpyDeg(0, 0, 0, abc.z(), abc.y(), abc.x()).rotationAngleTo(t) < 1e-13);
        }
    }

    @Test
    void halfTurnsAreHandled() {
        Transform3 t = Transform3.rotX(180);
        Quaternion q = Quaternion.of(t);
        assertEquals(1, Math.abs(q.x()), 1e-15);
        assertTrue(q.toTransform().rotationAngleTo(t) < 1e-15);
    }
}
