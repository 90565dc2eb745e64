package org.fresa.sole;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import org.fresa.geom.Box2;
import org.fresa.geom.Contour;
import org.fresa.geom.Vec2;
import org.fresa.geom.Vec3;
import org.fresa.model.Move;
import org.fresa.model.Toolpath;
import org.fresa.model.ToolpathSection;

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
public record MouldBlock(
        double pairGapMm,
        double mirrorStationMm,
        double mirrorOffsetMm,
        double blockEdgeMm,
        double blockLengthMm,
        Pattern pattern) {

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
            return new Pattern(
                    outlineBounds.maxY() - outlineBounds.minY(),
                    zero.y() - outlineBounds.minY(),
                    zero.x() - outlineBounds.minX());
        }
    }

    /**
     * The part zero of one size and foot in the machine frame, and the block's fit.
     *
     * @param machineMm ZP in the machine frame: (xz(ND), yz(ND))
     * @param mirrorLinePartXMm the mirror line's x in the right sole's part frame, -(XTANP(ND) + D/2)
     * @param patternLengthMm CP(ND)
     */
    public record PartZero(Foot foot, String size, Vec2 machineMm, double mirrorLinePartXMm, double patternLengthMm) {

        /**
         * A program of this foot written about its part zero {@code zeroMm} (the outline's frame,
         * the left foot already mirrored about x = zeroMm.x) moved to the machine frame: every
         * point shifted by {@code machineMm - zeroMm}, heights unchanged, arcs still arcs. Each
         * section's label names the foot and its part zero, so the operator reads them in the
         * program's comments.
         */
        public Toolpath placed(Toolpath partFrame, Vec2 zeroMm) {
            Vec3 by = Vec3.of(machineMm.minus(zeroMm), 0);
            List<ToolpathSection> out = new ArrayList<>();
            for (ToolpathSection s : partFrame.sections()) {
                List<Move> moves = new ArrayList<>(s.moves().size());
                for (Move m : s.moves()) {
                    moves.add(shifted(m, by));
                }
                String label = String.format(
                        java.util.Locale.ROOT,
                        "%s foot, part zero X%.3f Y%.3f: %s",
                        foot.id(),
                        machineMm.x(),
                        machineMm.y(),
                        s.label());
                out.add(new ToolpathSection(
                        label,
                        s.toolAxis(),
                        s.toolDiameterMm(),
                        s.toolNumber(),
                        s.spindleRpm(),
                        s.start().plus(by),
                        moves));
            }
            return new Toolpath(out);
        }

        /** An outline of this foot about {@code zeroMm} moved to the machine frame. */
        public Contour placed(Contour partFrame, Vec2 zeroMm) {
            return partFrame.translated(machineMm.minus(zeroMm));
        }

        private static Move shifted(Move m, Vec3 by) {
            if (m instanceof Move.Rapid r) {
                return new Move.Rapid(r.end().plus(by));
            } else if (m instanceof Move.Linear l) {
                return new Move.Linear(l.end().plus(by), l.feedMmPerMin());
            } else if (m instanceof Move.Circular c) {
                return new Move.Circular(
                        c.end().plus(by), c.center().plus(by), c.normal(), c.ccw(), c.turns(), c.feedMmPerMin());
            } else if (m instanceof Move.Dwell d) {
                return new Move.Dwell(d.end().plus(by), d.seconds());
            } else if (m instanceof Move.SpindleStop st) {
                return new Move.SpindleStop(st.end().plus(by));
            } else if (m instanceof Move.SpindleStart st) {
                return new Move.SpindleStart(st.end().plus(by), st.rpm(), st.clockwise());
            }
            throw new IllegalArgumentException("unknown move " + m);
        }
    }

    /** The mirror line x = DLM + E in the machine frame, about which the left sole is the right's image. */
    public double mirrorLineMachineXMm() {
        return mirrorStationMm + mirrorOffsetMm;
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
            return Optional.of(String.format(
                    java.util.Locale.ROOT,
                    "size %s: the pattern is %.3f mm long, the mould block only %.3f mm",
                    s.label(),
                    cp,
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
