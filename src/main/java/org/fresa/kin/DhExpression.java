package org.fresa.kin;

import java.util.Collections;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;

/**
 * A DH table cell written as an expression, such as {@code q2 - 90}, {@code 180/2} or
 * {@code -(pi/2)*180/pi + q3}: numbers, {@code pi}, the joint variables {@code q1 .. qN}, the
 * operators {@code + - * /} and parentheses. The value must be affine in the joint variables
 * (a product of two variables is refused), which is what a Denavit-Hartenberg row can carry.
 *
 * <p>The expression's units are the cell's (mm for a and d, degrees for alpha and theta);
 * {@code pi} is the number 3.14159..., not an angle of 180 degrees.
 *
 * @param constant the value with every joint variable at 0
 * @param coefficients joint number (1-based) to its coefficient; only non-zero coefficients
 */
public record DhExpression(double constant, Map<Integer, Double> coefficients) {

    public DhExpression {
        if (!Double.isFinite(constant)) {
            throw new IllegalArgumentException("the value is not finite: " + constant);
        }
        TreeMap<Integer, Double> c = new TreeMap<>();
        for (Map.Entry<Integer, Double> e : coefficients.entrySet()) {
            if (!Double.isFinite(e.getValue())) {
                throw new IllegalArgumentException("the coefficient of q" + e.getKey() + " is not finite");
            }
            if (e.getValue() != 0) {
                c.put(e.getKey(), e.getValue());
            }
        }
        coefficients = Collections.unmodifiableMap(c);
    }

    /** Whether no joint variable appears. */
    public boolean isConstant() {
        return coefficients.isEmpty();
    }

    /** The coefficient of q{@code joint} (0 when it does not appear). */
    public double coefficient(int joint) {
        return coefficients.getOrDefault(joint, 0.0);
    }

    /**
     * Reads an expression.
     *
     * @param text the cell as typed
     * @param maxJoint the highest joint number a variable may have
     * @throws IllegalArgumentException with a message for people (what is wrong and where)
     */
    public static DhExpression parse(String text, int maxJoint) {
        Objects.requireNonNull(text, "text");
        Parser p = new Parser(text, maxJoint);
        p.skipSpaces();
        if (p.atEnd()) {
            throw new IllegalArgumentException("empty: type a number or an expression such as q2 - 90");
        }
        Affine a = p.sum();
        p.skipSpaces();
        if (!p.atEnd()) {
            throw p.error("unexpected '" + text.charAt(p.pos) + "'");
        }
        return new DhExpression(a.c, a.q);
    }

    /** Affine value during parsing: c + sum q[j] * qj. */
    private static final class Affine {
        final double c;
        final TreeMap<Integer, Double> q;

        Affine(double c, TreeMap<Integer, Double> q) {
            this.c = c;
            this.q = q;
        }

        static Affine constant(double c) {
            return new Affine(c, new TreeMap<>());
        }

        boolean isConstant() {
            return q.values().stream().allMatch(v -> v == 0);
        }

        Affine plus(Affine o, double sign) {
            TreeMap<Integer, Double> m = new TreeMap<>(q);
            o.q.forEach((k, v) -> m.merge(k, sign * v, Double::sum));
            return new Affine(c + sign * o.c, m);
        }

        Affine scaled(double f) {
            TreeMap<Integer, Double> m = new TreeMap<>();
            q.forEach((k, v) -> m.put(k, v * f));
            return new Affine(c * f, m);
        }
    }

    private static final class Parser {
        final String s;
        final int maxJoint;
        int pos;

        Parser(String s, int maxJoint) {
            this.s = s;
            this.maxJoint = maxJoint;
        }

        boolean atEnd() {
            return pos >= s.length();
        }

        void skipSpaces() {
            while (pos < s.length() && Character.isWhitespace(s.charAt(pos))) {
                pos++;
            }
        }

        boolean eat(char c) {
            skipSpaces();
            if (pos < s.length() && s.charAt(pos) == c) {
                pos++;
                return true;
            }
            return false;
        }

        IllegalArgumentException error(String what) {
            return new IllegalArgumentException(what + " at character " + (pos + 1));
        }

        Affine sum() {
            Affine a = product();
            while (true) {
                if (eat('+')) {
                    a = a.plus(product(), 1);
                } else if (eat('-')) {
                    a = a.plus(product(), -1);
                } else {
                    return a;
                }
            }
        }

        Affine product() {
            Affine a = unary();
            while (true) {
                if (eat('*')) {
                    Affine b = unary();
                    if (a.isConstant()) {
                        a = b.scaled(a.c);
                    } else if (b.isConstant()) {
                        a = a.scaled(b.c);
                    } else {
                        throw error("a product of two joint variables cannot be a DH parameter");
                    }
                } else if (eat('/')) {
                    Affine b = unary();
                    if (!b.isConstant()) {
                        throw error("cannot divide by a joint variable");
                    }
                    if (b.c == 0) {
                        throw error("division by zero");
                    }
                    a = a.scaled(1 / b.c);
                } else {
                    return a;
                }
            }
        }

        Affine unary() {
            if (eat('-')) {
                return unary().scaled(-1);
            }
            if (eat('+')) {
                return unary();
            }
            return primary();
        }

        Affine primary() {
            skipSpaces();
            if (atEnd()) {
                throw error("expected a number, pi, q1..q" + maxJoint + " or '('");
            }
            if (eat('(')) {
                Affine a = sum();
                if (!eat(')')) {
                    throw error("expected ')'");
                }
                return a;
            }
            char ch = s.charAt(pos);
            if (Character.isDigit(ch) || ch == '.') {
                int start = pos;
                while (pos < s.length() && (Character.isDigit(s.charAt(pos)) || s.charAt(pos) == '.')) {
                    pos++;
                }
                if (pos < s.length() && (s.charAt(pos) == 'e' || s.charAt(pos) == 'E')) {
                    int save = pos;
                    pos++;
                    if (pos < s.length() && (s.charAt(pos) == '+' || s.charAt(pos) == '-')) {
                        pos++;
                    }
                    if (pos < s.length() && Character.isDigit(s.charAt(pos))) {
                        while (pos < s.length() && Character.isDigit(s.charAt(pos))) {
                            pos++;
                        }
                    } else {
                        pos = save;
                    }
                }
                String num = s.substring(start, pos);
                try {
                    return Affine.constant(Double.parseDouble(num));
                } catch (NumberFormatException e) {
                    pos = start;
                    throw error("'" + num + "' is not a number");
                }
            }
            if (Character.isLetter(ch)) {
                int start = pos;
                while (pos < s.length() && Character.isLetterOrDigit(s.charAt(pos))) {
                    pos++;
                }
                String word = s.substring(start, pos);
                String lower = word.toLowerCase(Locale.ROOT);
                if (lower.equals("pi")) {
                    return Affine.constant(Math.PI);
                }
                if (lower.matches("q[0-9]+")) {
                    int j = Integer.parseInt(lower.substring(1));
                    if (j < 1 || j > maxJoint) {
                        pos = start;
                        throw error("there is no joint " + word + " (q1..q" + maxJoint + ")");
                    }
                    TreeMap<Integer, Double> m = new TreeMap<>();
                    m.put(j, 1.0);
                    return new Affine(0, m);
                }
                pos = start;
                throw error("unknown name '" + word + "' (use numbers, pi and q1..q" + maxJoint + ")");
            }
            throw error("expected a number, pi, q1..q" + maxJoint + " or '(', not '" + ch + "'");
        }
    }
}
