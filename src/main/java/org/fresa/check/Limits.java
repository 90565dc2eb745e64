package org.fresa.check;

import java.util.List;
import java.util.Map;
import java.util.Objects;

/**
 * What a program is checked against: the machine's spindle and feed ranges, what switches the
 * cutting on (the spindle, or a sheet-cutting process's jet), how each tool may enter the
 * material, and the floor no move may pass.
 *
 * <p>Heights are in the program's frame and in millimetres (a 7M program's micrometres are
 * converted before they are compared).
 *
 * @param spindleMinRpm lowest spindle speed the machine turns, rpm
 * @param spindleMaxRpm highest spindle speed, rpm
 * @param feedMinMmPerMin lowest feed rate, mm/min
 * @param feedMaxMmPerMin highest feed rate, mm/min
 * @param head what cuts: the spindle, or a jet with its on and off words
 * @param tools by tool number (T word); tools not listed take {@code otherTools}
 * @param otherTools how the tools not in {@code tools} may enter the material
 * @param stock the material before cutting: a descent that ends outside it (grown by the tool's
 *     radius) cuts air; {@link Stock#UNKNOWN} when unknown: every descending feed move then counts
 * @param floorZMm the deepest height the job asks for (pocket bottom, through-hole exit), or NaN
 *     when the job states none (the floor rule then has nothing to compare)
 * @param breakthroughMm how far below the floor a move may go (a drill's tip and breakthrough)
 */
public record Limits(
        double spindleMinRpm,
        double spindleMaxRpm,
        double feedMinMmPerMin,
        double feedMaxMmPerMin,
        Head head,
        Map<Integer, ToolLimits> tools,
        ToolLimits otherTools,
        Stock stock,
        double floorZMm,
        double breakthroughMm) {

    /** The spindle range of a machine that says nothing else, rpm. */
    public static final double SPINDLE_MIN_RPM = 1;
    /** The spindle range of a machine that says nothing else, rpm. */
    public static final double SPINDLE_MAX_RPM = 100_000;
    /** The feed range of a machine that says nothing else, mm/min. */
    public static final double FEED_MIN_MM_PER_MIN = 0.1;
    /** The feed range of a machine that says nothing else, mm/min. */
    public static final double FEED_MAX_MM_PER_MIN = 100_000;

    public Limits {
        Objects.requireNonNull(head, "head");
        tools = Map.copyOf(tools);
        Objects.requireNonNull(otherTools, "otherTools");
        if (!(spindleMinRpm > 0 && spindleMinRpm <= spindleMaxRpm && Double.isFinite(spindleMaxRpm))) {
            throw new IllegalArgumentException(
                    "spindle range must be 0 < min <= max: " + spindleMinRpm + ".." + spindleMaxRpm);
        }
        if (!(feedMinMmPerMin > 0 && feedMinMmPerMin <= feedMaxMmPerMin && Double.isFinite(feedMaxMmPerMin))) {
            throw new IllegalArgumentException(
                    "feed range must be 0 < min <= max: " + feedMinMmPerMin + ".." + feedMaxMmPerMin);
        }
        Objects.requireNonNull(stock, "stock");
        if (!(breakthroughMm >= 0) || Double.isInfinite(breakthroughMm) || Double.isInfinite(floorZMm)) {
            throw new IllegalArgumentException("floor and breakthrough must be numbers, breakthrough >= 0");
        }
    }

    /**
     * A milling machine with the default ranges, its cutters not cutting at their centre (3
     * degrees), no material top or floor stated.
     */
    public static Limits milling() {
        return withDefaultRanges(Head.SPINDLE);
    }

    /** A sheet-cutting machine whose jet the words switch on and off (e.g. {@code M07}, {@code M08}). */
    public static Limits sheetCutting(String process, String onWords, String offWords) {
        return withDefaultRanges(new Head(process, Words.group(onWords), Words.group(offWords)));
    }

    /**
     * A machine that says nothing of its ranges, cutting with this head: its tools not cutting at
     * their centre, no material top or floor stated.
     */
    private static Limits withDefaultRanges(Head head) {
        return new Limits(
                SPINDLE_MIN_RPM,
                SPINDLE_MAX_RPM,
                FEED_MIN_MM_PER_MIN,
                FEED_MAX_MM_PER_MIN,
                head,
                Map.of(),
                ToolLimits.notCentreCutting(),
                Stock.UNKNOWN,
                Double.NaN,
                0);
    }

    /** These limits with tool {@code number} entering as {@code tool} says. */
    public Limits withTool(int number, ToolLimits tool) {
        Map<Integer, ToolLimits> m = new java.util.HashMap<>(tools);
        m.put(number, tool);
        return withMaterial(m, otherTools, stock, floorZMm, breakthroughMm);
    }

    /** These limits with every tool not listed entering as {@code tool} says. */
    public Limits withOtherTools(ToolLimits tool) {
        return withMaterial(tools, tool, stock, floorZMm, breakthroughMm);
    }

    /**
     * These limits with the material's top (the stock unbounded in X and Y and downwards), the
     * floor and the breakthrough below it.
     */
    public Limits withHeights(double materialTopZMm, double floorZMm, double breakthroughMm) {
        return withStock(Stock.below(materialTopZMm)).withFloor(floorZMm, breakthroughMm);
    }

    /** These limits with the stock. */
    public Limits withStock(Stock stock) {
        return withMaterial(tools, otherTools, stock, floorZMm, breakthroughMm);
    }

    /** These limits with the floor and the breakthrough below it. */
    public Limits withFloor(double floorZMm, double breakthroughMm) {
        return withMaterial(tools, otherTools, stock, floorZMm, breakthroughMm);
    }

    /** These limits with the machine's own spindle and feed ranges. */
    public Limits withRanges(double spindleMin, double spindleMax, double feedMin, double feedMax) {
        return new Limits(
                spindleMin, spindleMax, feedMin, feedMax, head, tools, otherTools, stock, floorZMm, breakthroughMm);
    }

    /** The same machine (ranges and head) with other tools, stock and floor. */
    private Limits withMaterial(
            Map<Integer, ToolLimits> ts, ToolLimits other, Stock s, double floor, double breakthrough) {
        return new Limits(
                spindleMinRpm,
                spindleMaxRpm,
                feedMinMmPerMin,
                feedMaxMmPerMin,
                head,
                ts,
                other,
                s,
                floor,
                breakthrough);
    }

    /** How tool {@code number} may enter the material. */
    public ToolLimits tool(int number) {
        return tools.getOrDefault(number, otherTools);
    }

    /**
     * The material before cutting, as a box in the program's frame (mm); infinite sides where
     * the job does not bound it.
     */
    public record Stock(double minXMm, double minYMm, double minZMm, double maxXMm, double maxYMm, double maxZMm) {
        /** Material everywhere: every descent counts as an entry. */
        public static final Stock UNKNOWN = new Stock(
                Double.NEGATIVE_INFINITY,
                Double.NEGATIVE_INFINITY,
                Double.NEGATIVE_INFINITY,
                Double.POSITIVE_INFINITY,
                Double.POSITIVE_INFINITY,
                Double.POSITIVE_INFINITY);

        public Stock {
            if (java.util.stream.DoubleStream.of(minXMm, minYMm, minZMm, maxXMm, maxYMm, maxZMm)
                    .anyMatch(Double::isNaN)) {
                throw new IllegalArgumentException("stock sides must be numbers");
            }
        }

        /** Material below the height, unbounded elsewhere. */
        public static Stock below(double topZMm) {
            return new Stock(
                    Double.NEGATIVE_INFINITY,
                    Double.NEGATIVE_INFINITY,
                    Double.NEGATIVE_INFINITY,
                    Double.POSITIVE_INFINITY,
                    Double.POSITIVE_INFINITY,
                    topZMm);
        }

        /** True when a tool of the radius at the point touches the stock by more than {@code clearMm}. */
        public boolean touches(org.fresa.geom.Vec3 p, double radiusMm, double clearMm) {
            double g = radiusMm - clearMm;
            return p.x() > minXMm - g
                    && p.x() < maxXMm + g
                    && p.y() > minYMm - g
                    && p.y() < maxYMm + g
                    && p.z() > minZMm - g
                    && p.z() < maxZMm - clearMm;
        }
    }

    /**
     * What switches the cutting on and off: the spindle ({@link #SPINDLE}: M3/M4 with S in range,
     * M5), or a sheet-cutting process's words (a block holding every word of {@code on}).
     *
     * @param process "spindle", or the process (plasma, laser, waterjet)
     * @param on the words that switch it on, empty for the spindle
     * @param off the words that switch it off, empty for the spindle
     */
    public record Head(String process, List<Words.Word> on, List<Words.Word> off) {
        /** A milling spindle. */
        public static final Head SPINDLE = new Head("spindle", List.of(), List.of());

        public Head {
            on = List.copyOf(on);
            off = List.copyOf(off);
        }

        public boolean isSpindle() {
            return on.isEmpty();
        }
    }
}
