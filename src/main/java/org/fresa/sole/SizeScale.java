package org.fresa.sole;

import java.util.Objects;
import org.fresa.geom.Vec2;

/**
 * The grading of one size as the tread needs it: the pantograph's factors about the grading
 * origin (the grading module computes them), the length axis being the job's y axis.
 *
 * @param label the size as named in file names ("40", "40.5")
 * @param origin the grading origin (mm), the fixed point of the pantograph and the foot of the
 *     mirror axis x = origin.x
 * @param widthFactor the x factor applied to the outline, shrinkage included (ALFA + CTM or
 *     ALFA (1 + CTM))
 * @param lengthFactor the y factor applied to the outline, shrinkage included
 * @param shrinkFactor 1 + CTM, the only scale the thesis applies to figures
 */
public record SizeScale(String label, Vec2 origin, double widthFactor, double lengthFactor, double shrinkFactor) {

    public SizeScale {
        Objects.requireNonNull(label, "label");
        Objects.requireNonNull(origin, "origin");
        if (!(widthFactor > 0) || !(lengthFactor > 0) || !(shrinkFactor > 0)) {
            throw new IllegalArgumentException("scale factors must be > 0");
        }
    }

    /** The base size without shrinkage: nothing moves. */
    public static SizeScale base(String label, Vec2 origin) {
        return new SizeScale(label, origin, 1, 1, 1);
    }

    /** The pantograph image of a point. */
    public Vec2 graded(Vec2 p) {
        return Vec2.of(
                origin.x() + widthFactor * (p.x() - origin.x()), origin.y() + lengthFactor * (p.y() - origin.y()));
    }
}
