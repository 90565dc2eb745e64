package org.fresa.grading;

import java.util.List;
import org.fresa.geom.Vec2;

/**
 * An element of an exactly graded outline: the affine image of a line (a line) or of a circular
 * arc (an elliptic arc). End points are exact images of the base's end points, so graded elements
 * join where the base's did.
 */
public sealed interface GradedCurve permits GradedLine, EllipticArc {

    Vec2 start();

    Vec2 end();

    /** The point at parameter fraction f in [0, 1] (by angle parameter for ellipse arcs). */
    Vec2 pointAt(double f);

    /** Smallest and largest value of p . dir over the curve, exact. */
    double[] extentAlong(Vec2 dir);

    /** The image under another pantograph map (an ellipse stays an ellipse). */
    GradedCurve mapped(PantographMap map);

    /**
     * Points from the start (included) towards the end (excluded) such that the chords between
     * consecutive points, and to the end, deviate from the curve by at most chordMm.
     */
    List<Vec2> sample(double chordMm);
}
