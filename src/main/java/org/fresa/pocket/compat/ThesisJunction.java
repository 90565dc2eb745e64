package org.fresa.pocket.compat;

import java.util.Optional;

/**
 * The thesis's intersection routine (GOTA.BAS lines 10690-11280) in its own order of operations
 * and precision: two consecutive elements of a subcontour, each a line {@code A·x + B·y = D} or a
 * circle (centre, radius), meet at the point their selector chooses.
 *
 * <ul>
 * <li>line × line: Cramer's rule; parallel lines end the program ({@code DET = 0}).
 * <li>line × circle: {@code y = (D - A·x)/B} substituted into the circle gives
 * {@code A'x² + B'x + C' = 0} with {@code B' = 2(-D·A + A·Y·B - X·B²)},
 * {@code A' = B² + A²}, {@code C' = D² - 2·D·Y·B + Y²·B² + X²·B² - R²·B²}; S takes the smaller
 * root, L the larger. A horizontal line (A = 0) gives x = X ± √(4X² - 4((y-Y)² - R² + X²))/2, a
 * vertical one (B = 0) the same in y.
 * <li>circle × circle: the radical line {@code 2(X2-X1)·x + 2(Y2-Y1)·y = -(X1² + Y1² - R1² + R2²
 * - X2² - Y2²)} with the first circle.
 * </ul>
 * Near tangency is decided on the discriminant: positive, the two roots are taken as computed
 * (so single-precision noise of a near-tangent pair moves the junction by the square root of
 * that noise); otherwise, when the line misses the circle by less than 100·COMPAR
 * ({@code DIST = |A·X + B·Y - D|/√(A² + B²) - R}, or the distance of the centres less both radii)
 * the discriminant is taken as 0; when it misses by more, the program ends; when it cuts, a
 * discriminant above -100·COMPAR (-50·COMPAR for horizontal and vertical lines) is taken as 0,
 * below it the program ends. Square roots are {@code ^.5} (EXP of LOG).
 */
public final class ThesisJunction {

    private ThesisJunction() {}

    /** One element's current coefficients: a line (a, b, d) or a circle (centre x, centre y, radius). */
    public record Carrier(boolean circle, Mbf a, Mbf b, Mbf d) {}

    /** A junction point in single precision. */
    public record Point(Mbf x, Mbf y) {}

    private static final Mbf TWO = Mbf.of(2);
    private static final Mbf FOUR = Mbf.of(4);
    private static final Mbf HALF = BasicNumbers.val(".5");
    private static final Mbf HUNDRED = Mbf.of(100);
    private static final Mbf FIFTY = Mbf.of(50);

    /**
     * The junction of p (ending) and q (starting), chosen by q's selector; empty where the
     * thesis's program stops ({@code END}).
     *
     * @param largeRoot q's selector is L
     * @param compar the thesis's tolerance, 1e-4 × the mean |D| or R of the input
     */
    public static Optional<Point> of(Carrier p, Carrier q, boolean largeRoot, Mbf compar) {
        if (!p.circle() && !q.circle()) {
            return lines(p, q);
        }
        Mbf a2, b2, d2, x1, y1, r1, dist;
        if (p.circle() && q.circle()) {
            x1 = p.a();
            y1 = p.b();
            r1 = p.d();
            Mbf x2 = q.a(), y2 = q.b(), r2 = q.d();
            a2 = TWO.times(x2.minus(x1));
            b2 = TWO.times(y2.minus(y1));
            d2 = x1.pow(2)
                    .plus(y1.pow(2))
                    .minus(r1.pow(2))
                    .plus(r2.pow(2))
                    .minus(x2.pow(2))
                    .minus(y2.pow(2))
                    .negate();
            dist = x2.minus(x1)
                    .pow(2)
                    .plus(y2.minus(y1).pow(2))
                    .pow(HALF)
                    .minus(r1)
                    .minus(r2);
        } else {
            Carrier line = p.circle() ? q : p;
            Carrier circle = p.circle() ? p : q;
            a2 = line.a();
            b2 = line.b();
            d2 = line.d();
            x1 = circle.a();
            y1 = circle.b();
            r1 = circle.d();
            dist = a2.times(x1)
                    .plus(b2.times(y1))
                    .minus(d2)
                    .dividedBy(a2.pow(2).plus(b2.pow(2)).pow(HALF))
                    .abs()
                    .minus(r1);
        }
        if (b2.isZero()) {
            return vertical(a2, d2, x1, y1, r1, dist, largeRoot, compar);
        }
        if (a2.isZero()) {
            return horizontal(b2, d2, x1, y1, r1, dist, largeRoot, compar);
        }
        Mbf bb = TWO.times(d2.negate().times(a2).plus(a2.times(y1).times(b2)).minus(x1.times(b2.pow(2))));
        Mbf aa = b2.pow(2).plus(a2.pow(2));
        Mbf cc = d2.pow(2)
                .minus(TWO.times(d2).times(y1).times(b2))
                .plus(y1.pow(2).times(b2.pow(2)))
                .plus(x1.pow(2).times(b2.pow(2)))
                .minus(r1.pow(2).times(b2.pow(2)));
        Mbf del = bb.pow(2).minus(FOUR.times(aa).times(cc));
        if (!del.greaterThan(Mbf.ZERO)) {
            if (dist.abs().lessThan(compar.times(HUNDRED))) {
                del = Mbf.ZERO;
            } else if (dist.greaterThan(Mbf.ZERO)) {
                return Optional.empty();
            } else if (del.greaterThan(HUNDRED.negate().times(compar))) {
                del = Mbf.ZERO;
            } else {
                return Optional.empty();
            }
        }
        Mbf root = del.pow(HALF);
        Mbf x01 = bb.negate().plus(root).dividedBy(TWO).dividedBy(aa);
        Mbf x02 = bb.negate().minus(root).dividedBy(TWO).dividedBy(aa);
        Mbf x = largeRoot ? (x01.greaterThan(x02) ? x01 : x02) : (x01.lessThan(x02) ? x01 : x02);
        Mbf y = d2.minus(a2.times(x)).dividedBy(b2);
        return Optional.of(new Point(x, y));
    }

    private static Optional<Point> lines(Carrier p, Carrier q) {
        Mbf det = p.a().times(q.b()).minus(q.a().times(p.b()));
        if (det.isZero()) {
            return Optional.empty();
        }
        Mbf x = p.b().negate().times(q.d()).plus(p.d().times(q.b())).dividedBy(det);
        Mbf y = p.d().negate().times(q.a()).plus(p.a().times(q.d())).dividedBy(det);
        return Optional.of(new Point(x, y));
    }

    /** Lines 11030-11140: the line y = D/B. */
    private static Optional<Point> horizontal(
            Mbf b2, Mbf d2, Mbf x1, Mbf y1, Mbf r1, Mbf dist, boolean largeRoot, Mbf compar) {
        Mbf y = d2.dividedBy(b2);
        Mbf es = y.minus(y1).pow(2).minus(r1.pow(2)).plus(x1.pow(2));
        Mbf del = FOUR.times(x1.pow(2)).minus(FOUR.times(es));
        Optional<Mbf> d = tangency(del, dist, compar);
        if (d.isEmpty()) {
            return Optional.empty();
        }
        Mbf root = d.get().pow(HALF);
        Mbf x01 = TWO.times(x1).minus(root).dividedBy(TWO);
        Mbf x02 = TWO.times(x1).plus(root).dividedBy(TWO);
        Mbf x = largeRoot ? (x01.greaterThan(x02) ? x01 : x02) : (x01.lessThan(x02) ? x01 : x02);
        return Optional.of(new Point(x, y));
    }

    /** Lines 11150-11260: the line x = D/A. */
    private static Optional<Point> vertical(
            Mbf a2, Mbf d2, Mbf x1, Mbf y1, Mbf r1, Mbf dist, boolean largeRoot, Mbf compar) {
        Mbf x = d2.dividedBy(a2);
        Mbf ds = x.minus(x1).pow(2).minus(r1.pow(2)).plus(y1.pow(2));
        Mbf del = FOUR.times(y1.pow(2)).minus(FOUR.times(ds));
        Optional<Mbf> d = tangency(del, dist, compar);
        if (d.isEmpty()) {
            return Optional.empty();
        }
        Mbf root = d.get().pow(HALF);
        Mbf y01 = TWO.times(y1).minus(root).dividedBy(TWO);
        Mbf y02 = TWO.times(y1).plus(root).dividedBy(TWO);
        Mbf y = largeRoot ? (y01.greaterThan(y02) ? y01 : y02) : (y01.lessThan(y02) ? y01 : y02);
        return Optional.of(new Point(x, y));
    }

    /** Lines 11062-11070 / 11191-11200: the discriminant of a horizontal or vertical line. */
    private static Optional<Mbf> tangency(Mbf del, Mbf dist, Mbf compar) {
        if (del.greaterThan(Mbf.ZERO)) {
            return Optional.of(del);
        }
        if (dist.abs().lessThan(compar.times(HUNDRED))) {
            return Optional.of(Mbf.ZERO);
        }
        if (dist.greaterThan(Mbf.ZERO)) {
            return Optional.empty();
        }
        if (del.greaterThan(FIFTY.negate().times(compar))) {
            return Optional.of(Mbf.ZERO);
        }
        return del.lessThan(Mbf.ZERO) ? Optional.empty() : Optional.of(del);
    }
}
