package org.fresa.sole;

import java.util.Objects;
import java.util.Optional;
import org.fresa.geom.Box2;
import org.fresa.geom.Vec2;

/**
 * The layout of a left and right sole in one mould block (Ahrens 1986, section 6.6.1): where the
 * part zero ZP (the heel circle's centre) of each foot lies in the machine frame, so that the two
 * patterns stand a gap apart, mirror images about one line, and centred along the block's length.
 *
 * <p>Only the right sole is defined; the left one is its mirror about the line x = DLM + E in the
 * machine frame, which is x = -(XTANP(ND) + D/2) in the right sole's part frame. The thesis's
 * equations, for a size ND with the width and length factors ALFA(ND) + CTM and BETA(ND) + CTM:
 * <pre>
 * left  xz(ND) = DLM + E - D/2 - XTANP(ND)          (6.1)
 * right xz(ND) = DLM + E + D/2 + XTANP(ND)          (6.2)
 * yz(ND) = S + DPI(ND) + (CM - CP(ND))/2            (6.6)
 * CP(ND) = CP (BETA(ND) + CTM), XTANP(ND) = XTANP (ALFA(ND) + CTM), DPI(ND) = DPI (BETA(ND) + CTM)
 * </pre>
 *
 * @param pairGapMm D, the x distance between the two patterns
 * @param mirrorStationMm DLM, the machine x of the tool's machining position on the fixture
 * @param mirrorOffsetMm E, from that position to the mirror line (fixture dependent; may be 0)
 * @param blockEdgeMm S, the machine y of the block's lower edge
 * @param blockLengthMm CM, the block's length along y
 * @param pattern the base size's extents about its part zero
 */
public record MouldBlock(double pairGapMm, double mirrorStationMm, double mirrorOffsetMm, double blockEdgeMm,
        double blockLengthMm, Pattern pattern) {

    public MouldBlock {
        atLeastZero(pairGapMm, "pairGapMm");
        finite(mirrorStationMm, "mirrorStationMm");
        finite(mirrorOffsetMm, "mirrorOffsetMm");
        finite(blockEdgeMm, "blockEdgeMm");
        positive(blockLengthMm, "blockLengthMm");
        Objects.requireNonNull(pattern, "pattern");
    }

    /**
     * The base size's extents about its part zero, as the thesis's layout needs them.
     *
     * @param lengthMm CP, the pattern's length along y
     * @param heelOverhangMm DPI, from ZP down to the pattern's lowest point
     * @param innerReachMm XTANP, from ZP to the tangent parallel to y on the inner side (towards
     *     the other foot, -x for the right sole)
     */
    public record Pattern(double lengthMm, double heelOverhangMm, double innerReachMm) {
        public Pattern {
            positive(lengthMm, "lengthMm");
            finite(heelOverhangMm, "heelOverhangMm");
            finite(innerReachMm, "innerReachMm");
        }

        /** The extents measured on the right sole's outline, whose part zero is {@code zero}. */
        public static Pattern measured(Box2 outlineBounds, Vec2 zero) {
            return new Pattern(outlineBounds.maxY() - outlineBounds.minY(), zero.y() - outlineBounds.minY(),
                    zero.x() - outlineBounds.minX());
        }
    }

    /** The part zero of one size and foot in the machine frame, and the block's fit. */
    public record PartZero(Foot foot, String size, Vec2 machineMm, double mirrorLinePartXMm, double patternLengthMm) {
    }

    /** Where ZP of {@code foot} lies for the size {@code s} (equations 6.1, 6.2, 6.6 to 6.9). */
    public PartZero partZero(SizeScale s, Foot foot) {
        double xtanp = pattern.innerReachMm() * s.widthFactor();
        double dpi = pattern.heelOverhangMm() * s.lengthFactor();
        double cp = pattern.lengthMm() * s.lengthFactor();
        double mirror = mirrorStationMm + mirrorOffsetMm;
        double x = foot == Foot.RIGHT ? mirror + pairGapMm / 2 + xtanp : mirror - pairGapMm / 2 - xtanp;
        double y = blockEdgeMm + dpi + (blockLengthMm - cp) / 2;
        return new PartZero(foot, s.label(), Vec2.of(x, y), -(xtanp + pairGapMm / 2), cp);
    }

    /**
     * Why the size does not fit the block (its graded pattern longer than the block), or empty.
     * The thesis does not check it; its insert block (CM 285) takes sizes up to 41 only.
     */
    public Optional<String> misfit(SizeScale s) {
        double cp = pattern.lengthMm() * s.lengthFactor();
        if (cp > blockLengthMm) {
            return Optional.of(String.format(java.util.Locale.ROOT,
                    "size %s: the pattern is %.3f mm long, the mould block only %.3f mm", s.label(), cp,
                    blockLengthMm));
        }
        return Optional.empty();
    }

    private static void finite(double v, String name) {
        if (!Double.isFinite(v)) {
            throw new IllegalArgumentException(name + " must be finite: " + v);
        }
    }

    private static void atLeastZero(double v, String name) {
        if (!(v >= 0) || Double.isInfinite(v)) {
            throw new IllegalArgumentException(name + " must be finite and >= 0: " + v);
        }
    }

    private static void positive(double v, String name) {
        if (!(v > 0) || Double.isInfinite(v)) {
            throw new IllegalArgumentException(name + " must be finite and > 0: " + v);
        }
    }
}
