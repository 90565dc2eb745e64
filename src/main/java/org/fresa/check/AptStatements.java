package org.fresa.check;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.regex.Pattern;
import org.fresa.geom.Vec3;

/**
 * Reads an APT / CL-data program ({@code fresa --post apt}) statement by statement into the same
 * steps the G-code check reads from blocks, so that the same {@link ProgramCheck#RULES} decide it.
 *
 * <p>The statements read, one per line ({@code $$} starts a comment): {@code PARTNO},
 * {@code UNITS/MM}, {@code LOADTL/n} (a tool change: the spindle stops, as after M06),
 * {@code CUTTER/d[,r]}, {@code FEDRAT/f[,MMPM]}, {@code SPINDL/rpm[,CLW|CCLW]}, {@code SPINDL/ON},
 * {@code SPINDL/OFF}, {@code COOLNT/...}, {@code RAPID} (the next motion only is a rapid),
 * {@code GOTO/x,y,z[,i,j,k]}, {@code GODLTA/dx,dy,dz}, {@code CIRCLE/xc,yc,zc,i,j,k,r} followed by
 * the {@code GOTO} of the arc's end (counter-clockwise about i,j,k; a helix rises uniformly from
 * the start's height to the end's), {@code DELAY/s}, {@code FINI} (the spindle stops).
 *
 * <p>Each statement is given to the rules as a block of address words: X, Y, Z the point of a
 * GOTO or GODLTA, I, J, K and R the centre and radius of a CIRCLE (coordinates), F the feed, S the
 * spindle speed, T the tool, P a dwell's time. What the words cannot say is refused as a statement
 * that cannot be read: an unknown statement, units other than mm, a cutter of no diameter, a
 * CIRCLE whose axis is not a unit vector, whose end is not on it, or that is not followed by its
 * GOTO, a continued statement.
 */
final class AptStatements {

    private static final Pattern NUMBER = Pattern.compile("[+-]?(\\d+(\\.\\d*)?|\\.\\d+)");

    /** How far the end of an arc may lie off its circle: the written digits of both, mm. */
    private static final double ON_CIRCLE_MM = 0.002;

    private AptStatements() {}

    /** Checks the whole program against the limits, statement by statement. */
    static ProgramCheck.Verdict check(String program, Limits limits) {
        String[] lines = program.split("\r?\n|\r", -1);
        Machine m = new Machine(limits);
        for (int i = 0; i < lines.length; i++) {
            Step step = m.execute(i + 1, lines[i]);
            for (Rule r : ProgramCheck.RULES) {
                String why = r.broken(step, limits);
                if (why != null) {
                    Words.Block b = step.block();
                    return new ProgramCheck.Verdict(
                            Optional.of(new Failure(b.line(), "line " + b.line(), b.text(), r, why)), lines.length);
                }
            }
            step.material().cut(step, limits);
            if (step.block().problem().isPresent()) {
                break;
            }
        }
        return new ProgramCheck.Verdict(Optional.empty(), lines.length);
    }

    /** One statement: its major word, its arguments as written (numbers or minor words). */
    record Statement(String word, List<String> args) {}

    /** The statement of a line, empty for a blank line or a comment. */
    static Optional<Statement> parse(String text) {
        String t = text;
        int comment = t.indexOf("$$");
        if (comment >= 0) {
            t = t.substring(0, comment);
        }
        t = t.strip();
        if (t.isEmpty()) {
            return Optional.empty();
        }
        if (t.toUpperCase(Locale.ROOT).startsWith("PARTNO")) {
            return Optional.of(new Statement("PARTNO", List.of()));
        }
        int slash = t.indexOf('/');
        String word = (slash < 0 ? t : t.substring(0, slash)).strip().toUpperCase(Locale.ROOT);
        List<String> args = new ArrayList<>();
        if (slash >= 0) {
            for (String a : t.substring(slash + 1).split(",", -1)) {
                args.add(a.strip().toUpperCase(Locale.ROOT));
            }
        }
        return Optional.of(new Statement(word, args));
    }

    /** The machine's state as the statements run. */
    private static final class Machine extends MachineState {
        private boolean rapidNext;
        private Circle circle;

        Machine(Limits limits) {
            super(limits);
        }

        private record Circle(Vec3 centre, Vec3 axis, double radiusMm) {}

        Step execute(int line, String text) {
            String t = text.strip();
            if (t.startsWith("$$")) {
                axis = ProgramCheck.axisOfComment(t);
            }
            Optional<Statement> parsed = parse(text);
            if (parsed.isEmpty()) {
                return idle(new Words.Block(line, text, List.of(), Optional.empty()), false);
            }
            Statement st = parsed.get();
            List<Words.Word> words = new ArrayList<>();
            String problem = problem(st, words);
            Words.Block b = new Words.Block(line, text, words, Optional.ofNullable(problem));
            if (problem != null) {
                return idle(b, false);
            }
            if (circle != null && !st.word().equals("GOTO")) {
                return idle(
                        new Words.Block(
                                line,
                                text,
                                words,
                                Optional.of(
                                        "a CIRCLE/ must be followed by the GOTO/ of the arc's end, not " + st.word())),
                        false);
            }
            switch (st.word()) {
                case "GOTO", "GODLTA": {
                    boolean delta = st.word().equals("GODLTA");
                    double nx = delta ? x + words.get(0).value() : words.get(0).value();
                    double ny = delta ? y + words.get(1).value() : words.get(1).value();
                    double nz = delta ? z + words.get(2).value() : words.get(2).value();
                    boolean rapid = rapidNext;
                    rapidNext = false;
                    Circle c = circle;
                    circle = null;
                    if (c != null && rapid) {
                        return idle(
                                new Words.Block(
                                        line,
                                        text,
                                        words,
                                        Optional.of("the GOTO/ of a CIRCLE/ after RAPID: an arc is a feed motion")),
                                false);
                    }
                    List<Vec3> path = List.of();
                    boolean inPlane = false;
                    double horizontal = 0;
                    Vec3 end = new Vec3(nx, ny, nz);
                    boolean known = Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z);
                    if (known && c != null) {
                        Vec3 start = new Vec3(x, y, z);
                        Arc arc = arc(start, end, c);
                        if (arc == null) {
                            return idle(
                                    new Words.Block(
                                            line,
                                            text,
                                            words,
                                            Optional.of("the arc's start and end are "
                                                    + "not on the CIRCLE/ before it (radius " + Num.of(c.radiusMm())
                                                    + " mm)")),
                                    false);
                        }
                        path = arc.points();
                        inPlane = Math.abs(c.axis().z()) > 1 - 1e-9;
                        horizontal = arc.horizontalMm();
                    } else if (known) {
                        path = List.of(new Vec3(x, y, z), end);
                    } else if (Double.isFinite(nx + ny + nz)) {
                        path = List.of(end);
                    }
                    x = nx;
                    y = ny;
                    z = nz;
                    Step s = new Step(
                            b,
                            NcDialect.APT,
                            !rapid,
                            path,
                            inPlane,
                            horizontal,
                            on,
                            rpm,
                            feed,
                            tool,
                            false,
                            axis,
                            drilled,
                            material);
                    ProgramCheck.madeHole(s, limits, drilled);
                    return s;
                }
                case "CIRCLE": {
                    Vec3 n = new Vec3(value(st, 3), value(st, 4), value(st, 5));
                    circle = new Circle(
                            new Vec3(value(st, 0), value(st, 1), value(st, 2)), n.times(1 / n.norm()), value(st, 6));
                    return idle(b, false);
                }
                case "RAPID":
                    rapidNext = true;
                    return idle(b, false);
                case "FEDRAT":
                    feed = words.get(0).value();
                    return idle(b, false);
                case "SPINDL": {
                    String a = st.args().get(0);
                    if (a.equals("OFF")) {
                        on = false;
                    } else if (a.equals("ON")) {
                        on = true;
                    } else {
                        rpm = words.get(0).value();
                        on = true;
                    }
                    return idle(b, false);
                }
                case "LOADTL": {
                    Step s = idle(b, false);
                    tool = (int) words.get(0).value();
                    on = on && !limits.head().isSpindle();
                    return s;
                }
                case "DELAY":
                    return idle(b, true);
                case "FINI": {
                    Step s = idle(b, false);
                    on = false;
                    return s;
                }
                default:
                    return idle(b, false);
            }
        }

        private Step idle(Words.Block b, boolean dwell) {
            return new Step(
                    b, NcDialect.APT, false, List.of(), false, 0, on, rpm, feed, tool, dwell, axis, drilled, material);
        }

        /** What makes the statement unreadable, or null; its words added to {@code words}. */
        private static String problem(Statement st, List<Words.Word> words) {
            List<String> a = st.args();
            switch (st.word()) {
                case "PARTNO", "COOLNT":
                    return null;
                case "RAPID", "FINI":
                    return a.isEmpty() ? null : st.word() + " takes no arguments";
                case "UNITS":
                    return a.equals(List.of("MM")) ? null : "UNITS/" + String.join(",", a) + ": only UNITS/MM is read";
                case "GOTO": {
                    if (a.size() != 3 && a.size() != 6) {
                        return "GOTO/ takes x,y,z or x,y,z,i,j,k";
                    }
                    return numbers(a, new String[] {"X", "Y", "Z", "I", "J", "K"}, words);
                }
                case "GODLTA":
                    return a.size() != 3 ? "GODLTA/ takes dx,dy,dz" : numbers(a, new String[] {"X", "Y", "Z"}, words);
                case "CIRCLE": {
                    if (a.size() != 7) {
                        return "CIRCLE/ takes xc,yc,zc,i,j,k,r";
                    }
                    String why = numbers(a, new String[] {"I", "J", "K", "AXISI", "AXISJ", "AXISK", "R"}, words);
                    if (why != null) {
                        return why;
                    }
                    double n = Math.sqrt(Math.pow(words.get(3).value(), 2)
                            + Math.pow(words.get(4).value(), 2)
                            + Math.pow(words.get(5).value(), 2));
                    if (Math.abs(n - 1) > 1e-4) {
                        return "the CIRCLE/'s axis " + a.get(3) + "," + a.get(4) + "," + a.get(5)
                                + " is not a unit vector";
                    }
                    return words.get(6).value() > 0 ? null : "the CIRCLE/'s radius must be > 0";
                }
                case "FEDRAT":
                    if (a.isEmpty()
                            || a.size() > 2
                            || (a.size() == 2 && !a.get(1).equals("MMPM"))) {
                        return "FEDRAT/ takes f or f,MMPM";
                    }
                    return numbers(a.subList(0, 1), new String[] {"F"}, words);
                case "SPINDL":
                    if (a.size() == 1 && (a.get(0).equals("OFF") || a.get(0).equals("ON"))) {
                        return null;
                    }
                    if (a.isEmpty()
                            || a.size() > 2
                            || (a.size() == 2
                                    && !a.get(1).equals("CLW")
                                    && !a.get(1).equals("CCLW"))) {
                        return "SPINDL/ takes rpm, rpm,CLW, rpm,CCLW, ON or OFF";
                    }
                    return numbers(a.subList(0, 1), new String[] {"S"}, words);
                case "LOADTL":
                    return a.size() != 1 ? "LOADTL/ takes the tool number" : numbers(a, new String[] {"T"}, words);
                case "CUTTER": {
                    if (a.isEmpty() || a.size() > 2) {
                        return "CUTTER/ takes d or d,r";
                    }
                    String why = numbers(a, new String[] {"CUTTER", "CORNER"}, words);
                    return why != null ? why : words.get(0).value() > 0 ? null : "the CUTTER/'s diameter must be > 0";
                }
                case "DELAY":
                    return a.size() != 1 ? "DELAY/ takes the time in seconds" : numbers(a, new String[] {"P"}, words);
                default:
                    if (st.word().endsWith("$") || a.stream().anyMatch(s -> s.endsWith("$"))) {
                        return "continued statements ($) are not read";
                    }
                    return "'" + st.word() + "' is not a statement Fresa's APT reader takes";
            }
        }

        private static String numbers(List<String> args, String[] addresses, List<Words.Word> words) {
            for (int i = 0; i < args.size(); i++) {
                String s = args.get(i);
                if (!NUMBER.matcher(s).matches()) {
                    return "'" + s + "' where a number was expected";
                }
                if (s.length() > Words.MAX_NUMBER_CHARS) {
                    return "number " + s + " has " + s.length() + " characters: at most " + Words.MAX_NUMBER_CHARS;
                }
                words.add(new Words.Word(addresses[i], Double.parseDouble(s), s));
            }
            return null;
        }

        private static double value(Statement st, int i) {
            return Double.parseDouble(st.args().get(i));
        }

        private record Arc(List<Vec3> points, double horizontalMm) {}

        /**
         * The arc from start to end counter-clockwise about the circle's axis, sampled every
         * degree; null when the start or the end is not on the circle.
         */
        private static Arc arc(Vec3 start, Vec3 end, Circle c) {
            Vec3 n = c.axis();
            Vec3 u = inPlane(start.minus(c.centre()), n);
            Vec3 e = inPlane(end.minus(c.centre()), n);
            double r0 = u.norm();
            double r1 = e.norm();
            if (Math.abs(r0 - c.radiusMm()) > ON_CIRCLE_MM || Math.abs(r1 - c.radiusMm()) > ON_CIRCLE_MM || !(r0 > 0)) {
                return null;
            }
            double angle = Math.atan2(u.cross(e).dot(n), u.dot(e));
            double sweep = angle <= 1e-9 ? angle + 2 * Math.PI : angle;
            double rise = end.minus(start).dot(n);
            Vec3 uHat = u.times(1 / r0);
            Vec3 v = n.cross(uHat);
            Vec3 base = c.centre().plus(n.times(start.minus(c.centre()).dot(n)));
            int count = (int) Math.max(2, Math.ceil(Math.toDegrees(sweep)));
            List<Vec3> pts = new ArrayList<>(count + 1);
            for (int i = 0; i <= count; i++) {
                double f = (double) i / count;
                double a = sweep * f;
                double r = r0 + (r1 - r0) * f;
                Vec3 p = base.plus(n.times(rise * f))
                        .plus(uHat.times(r * Math.cos(a)))
                        .plus(v.times(r * Math.sin(a)));
                pts.add(i == 0 ? start : i == count ? end : p);
            }
            return new Arc(pts, 0.5 * (r0 + r1) * sweep);
        }

        private static Vec3 inPlane(Vec3 v, Vec3 n) {
            return v.minus(n.times(v.dot(n)));
        }
    }
}
