package org.fresa.chart;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class ViewPlaneTest {

    @ParameterizedTest
    @CsvSource(textBlock = """
            0,    0,   1, TOP_XY,   1, 2, x (mm), y (mm)
            0,   -1,   0, FRONT_XZ, 1, 3, x (mm), z (mm)
            1,    0.5, 0, SIDE_YZ,  2, 3, y (mm), z (mm)
            0.5,  0.5, 0.5, TOP_XY, 1, 2, x (mm), y (mm)
            """)
    void aViewLooksAlongTheAxisMostlyFollowedAndNamesItsAxes(
            double ax, double ay, double az, ViewPlane view, double h, double v, String horizontal, String vertical) {
        ViewPlane p = ViewPlane.along(Vec3.of(ax, ay, az));
        assertAll(
                () -> assertEquals(view, p),
                () -> assertEquals(Vec2.of(h, v), p.project(Vec3.of(1, 2, 3))),
                () -> assertEquals(horizontal, p.axes().horizontal()),
                () -> assertEquals(vertical, p.axes().vertical()));
    }

    @ParameterizedTest
    @CsvSource(textBlock = """
            TOP_XY,   true
            SIDE_YZ,  true
            FRONT_XZ, false
            """)
    void onlyTheFrontViewSeesATurnAboutItsAxisReversed(ViewPlane view, boolean keeps) {
        // a quarter turn ccw about the positive view axis: from the first plot axis towards the second
        Vec3 a = view == ViewPlane.TOP_XY ? Vec3.UNIT_X : view == ViewPlane.SIDE_YZ ? Vec3.UNIT_Y : Vec3.UNIT_Z;
        Vec3 b = view.viewAxis().cross(a);
        double turn = view.project(a).cross(view.project(b));
        assertEquals(keeps, turn > 0);
        assertEquals(keeps, view.keepsSense());
    }
}
