package org.fresa.kin;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import org.matheclipse.core.eval.ExprEvaluator;
import org.matheclipse.core.interfaces.IExpr;

/**
 * The forward kinematics and geometric Jacobian of a DH table as Symja expressions (the thesis
 * built its Jacobian this way), for showing and exporting; the numeric code does not use them.
 *
 * <p>Cells are expressions in q1..qn in mm and degrees, such as {@code q2 - 90}; the joint i is
 * revolute when its theta cell mentions q_i and prismatic when its d cell does. Symja starts
 * slowly (a second or more), so the evaluator is created on first use; calls are serialised.
 */
public final class SymbolicKinematics {

    private SymbolicKinematics() {}

    /**
     * One DH row as expressions.
     *
     * @param a link length (mm)
     * @param d link offset (mm)
     * @param alphaDeg twist (deg)
     * @param thetaDeg joint angle (deg)
     */
    public record DhRow(String a, String d, String alphaDeg, String thetaDeg) {
        public DhRow {
            Objects.requireNonNull(a, "a");
            Objects.requireNonNull(d, "d");
            Objects.requireNonNull(alphaDeg, "alphaDeg");
            Objects.requireNonNull(thetaDeg, "thetaDeg");
        }
    }

    /**
     * The expressions.
     *
     * @param transform the 4x4 tool pose (rows), mm
     * @param jacobian the 6 x n geometric Jacobian (rows vx, vy, vz in mm, wx, wy, wz), per rad or mm;
     *     empty when not asked for
     */
    public record Result(List<List<String>> transform, List<List<String>> jacobian) {
        public Result {
            transform = List.copyOf(transform);
            jacobian = List.copyOf(jacobian);
        }
    }

    private static ExprEvaluator evaluator;

    private static ExprEvaluator evaluator() {
        if (evaluator == null) {
            ExprEvaluator e = new ExprEvaluator();
            e.eval("fresaDh[t_,d_,aa_,al_]:={{Cos[t],-Sin[t]*Cos[al],Sin[t]*Sin[al],aa*Cos[t]},"
                    + "{Sin[t],Cos[t]*Cos[al],-Cos[t]*Sin[al],aa*Sin[t]},{0,Sin[al],Cos[al],d},{0,0,0,1}}");
            evaluator = e;
        }
        return evaluator;
    }

    /** The rows of a numeric chain, with q_i written into the cell that carries it. */
    public static List<DhRow> rowsOf(DenavitHartenbergChain chain) {
        List<DhRow> rows = new ArrayList<>();
        int i = 1;
        for (DhJoint j : chain.joints()) {
            String q = "q" + i++;
            String a = num(j.aMm());
            String alpha = num(j.alphaDeg());
            if (j.type() == JointType.REVOLUTE) {
                rows.add(new DhRow(a, num(j.dMm()), alpha, withOffset(q, j.thetaDeg())));
            } else {
                rows.add(new DhRow(a, withOffset(q, j.dMm()), alpha, num(j.thetaDeg())));
            }
        }
        return rows;
    }

    private static String withOffset(String q, double c) {
        return c == 0 ? q : q + (c > 0 ? " + " : " - ") + num(Math.abs(c));
    }

    private static String num(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        return String.format(Locale.ROOT, "%s", v);
    }

    /**
     * The symbolic forward kinematics (and, if asked, the geometric Jacobian) of the rows.
     *
     * @throws IllegalArgumentException when a cell is not an expression Symja reads
     */
    public static synchronized Result of(List<DhRow> rows, boolean withJacobian) {
        ExprEvaluator e = evaluator();
        int n = rows.size();
        e.eval("fresaT0=IdentityMatrix[4]");
        for (int i = 0; i < n; i++) {
            DhRow r = rows.get(i);
            String a = "fresaT" + i + ".fresaDh[(" + r.thetaDeg() + ")*Pi/180,(" + r.d() + "),(" + r.a() + "),("
                    + r.alphaDeg() + ")*Pi/180]";
            IExpr res = e.eval("fresaT" + (i + 1) + "=" + a);
            if (res.isAST() && res.toString().startsWith("Syntax")) {
                throw new IllegalArgumentException("joint " + (i + 1) + ": not an expression: " + res);
            }
        }
        List<List<String>> t = new ArrayList<>();
        for (int r = 1; r <= 4; r++) {
            List<String> row = new ArrayList<>();
            for (int c = 1; c <= 4; c++) {
                row.add(text(e.eval("fresaT" + n + "[[" + r + "," + c + "]]")));
            }
            t.add(row);
        }
        List<List<String>> jac = new ArrayList<>();
        if (withJacobian) {
            List<List<String>> cols = new ArrayList<>();
            String on = "fresaT" + n + "[[1;;3,4]]";
            for (int i = 0; i < n; i++) {
                String z = "fresaT" + i + "[[1;;3,3]]";
                String o = "fresaT" + i + "[[1;;3,4]]";
                boolean revolute = rows.get(i).thetaDeg().contains("q" + (i + 1));
                String col =
                        revolute ? "Join[Cross[" + z + "," + on + "-" + o + "]," + z + "]" : "Join[" + z + ",{0,0,0}]";
                IExpr v = e.eval(col);
                List<String> entries = new ArrayList<>();
                for (int r = 1; r <= 6; r++) {
                    entries.add(text(v.getAt(r)));
                }
                cols.add(entries);
            }
            for (int r = 0; r < 6; r++) {
                List<String> row = new ArrayList<>();
                for (int c = 0; c < n; c++) {
                    row.add(cols.get(c).get(r));
                }
                jac.add(row);
            }
        }
        return new Result(t, jac);
    }

    /** The value of an expression in q1..qn (deg / mm) for the given joint values. */
    public static synchronized double evaluate(String expression, double... q) {
        StringBuilder rules = new StringBuilder("{");
        for (int i = 0; i < q.length; i++) {
            if (i > 0) {
                rules.append(',');
            }
            rules.append("q").append(i + 1).append("->").append(new java.math.BigDecimal(q[i]).toPlainString());
        }
        rules.append('}');
        IExpr v = evaluator().eval("N[(" + expression + ")/." + rules + "]");
        return v.evalf();
    }

    private static String text(IExpr e) {
        return e.toString().replace("\n", "").replace("\r", "");
    }
}
