package org.fresa.grading;

import java.util.List;
import org.fresa.geom.Vec2;

/** A graded straight element (the image of a line is a line). */
public record GradedLine(Vec2 start, Vec2 end) implements GradedCurve {

    @Override
    public Vec2 pointAt(double f) {
        return start.interpolate(end, f);
    }

    @Override
    public double[] extentAlong(Vec2 dir) {
        double a = start.dot(dir);
        double b = end.dot(dir);
        return new double[] {Math.min(a, b), Math.max(a, b)};
    }

    @Override
    public GradedLine mapped(PantographMap map) {
        return new GradedLine(map.apply(start), map.apply(end));
    }

    @Override
    public List<Vec2> sample(double chordMm) {
        return List.of(start);
    }
}
