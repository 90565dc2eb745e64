package org.fresa.sole;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import org.fresa.geom.Tolerance;
import org.fresa.geom.Vec2;
import org.fresa.model.CamInputException;

/**
 * Builds {@link TreadFigure}s from a macro name and keyword parameters, as the thesis's
 * {@code CALL/SUB1A,XA1=-40,YA1=-41,...} gives them.
 *
 * <p>Keywords are the thesis's (case-insensitive). {@code I}, {@code PROF} and {@code AVAN} are
 * accepted and ignored (depth and feed are the tread's); {@code CTM} is accepted only as 0, since
 * shrinkage is the job's. The arc macros take {@code CCW=1} for a counter-clockwise sense
 * (default clockwise, as in every thesis test program).
 */
public final class TreadFigures {

    /**
     * Every macro name: the thesis's, in its order, then the special designs of its Table 5.2
     * (groups F to J, {@link SpecialDesigns}).
     */
    public static final List<String> MACROS = List.of(
            "PRIM", "NOVO", "SUB1A", "SUB1B", "SUB2", "SUB3A", "SUB3B", "SUB3E", "SUB4", "SUB5A", "SUB5B", "SUB5E",
            "SUB7A", "SUB7B", "SUB8A", "SUB8B", "SUB9A", "SUB9B", "PARAL", "COLMEIA", "PIRAM", "TEXTURA", "LOGO");

    private static final Map<String, List<String>> PARAMS = new LinkedHashMap<>();

    static {
        PARAMS.put("PRIM", List.of("XI", "YI", "XA1", "YA1"));
        PARAMS.put("NOVO", List.of("XF1", "YF1", "XF2", "YF2"));
        PARAMS.put("SUB1A", List.of("XA1", "YA1", "XB1", "YC1", "XC1", "XD1"));
        PARAMS.put("SUB1B", List.of("XA1", "YA1", "YB1", "YC1", "XC1", "YD1"));
        PARAMS.put("SUB2", List.of("XA2", "YA2", "XB2", "YB2"));
        PARAMS.put("SUB3A", List.of("XC", "YC", "RA", "XA3", "XB3"));
        PARAMS.put("SUB3B", List.of("XC", "YC", "RA", "XA3", "XB3"));
        PARAMS.put("SUB3E", List.of("XC", "YC", "RA", "XA3", "XB3", "AFAS", "N"));
        PARAMS.put("SUB4", List.of("XC", "YC", "RA", "XA4", "YA4", "XB4", "YB4"));
        PARAMS.put("SUB5A", List.of("XC1", "YC1", "XC2", "YC2", "XT", "YT", "XA5", "XB5"));
        PARAMS.put("SUB5B", List.of("XC1", "YC1", "XC2", "YC2", "XT", "YT", "XA5", "XB5"));
        PARAMS.put("SUB5E", List.of("XC1", "YC1", "XC2", "YC2", "XT", "YT", "XA5", "XB5", "AFAS", "N"));
        PARAMS.put("SUB7A", List.of("XA7", "YA7", "XB7", "YB7", "XC7", "YC7"));
        PARAMS.put("SUB7B", List.of("XB7", "YB7", "XC7", "YC7"));
        PARAMS.put("SUB8A", List.of("XA8", "YA8", "XB8", "YB8", "XC8", "YC8", "XD8", "YD8"));
        PARAMS.put("SUB8B", List.of("XB8", "YB8", "XC8", "YC8", "XD8", "YD8"));
        PARAMS.put("SUB9A", List.of("XA9", "YA9", "XB9", "YB9", "XC9", "YC9", "XD9", "YD9", "XE9", "YE9"));
        PARAMS.put("SUB9B", List.of("XB9", "YB9", "XC9", "YC9", "XD9", "YD9", "XE9", "YE9"));
        PARAMS.put("PARAL", List.of("XO", "YO", "A", "B", "ANG", "NA", "NB"));
        PARAMS.put("COLMEIA", List.of("XO", "YO", "S", "NX", "NY"));
        PARAMS.put("PIRAM", List.of("XO", "YO", "P", "ANG", "N1", "N2"));
        PARAMS.put("TEXTURA", List.of("XO", "YO", "L", "P", "ANG", "N", "DASH", "GAP"));
        PARAMS.put("LOGO", List.of("X", "Y", "H"));
    }

    private static final Map<String, String> EXAMPLES = Map.ofEntries(
            Map.entry("PRIM", "XI=-40,YI=-10,XA1=0,YA1=0"),
            Map.entry("NOVO", "XF1=40,YF1=-10,XF2=40,YF2=-5"),
            Map.entry("SUB1A", "XA1=-40,YA1=-41,XB1=40,XC1=40,YC1=-31,XD1=-40"),
            Map.entry("SUB1B", "XA1=-45,YA1=210.6,YB1=181,XC1=-30,YC1=184,YD1=220"),
            Map.entry("SUB2", "XA2=-40,YA2=10,XB2=10,YB2=0"),
            Map.entry("SUB3A", "XC=-30,YC=-35,RA=5,XA3=-35,XB3=-25"),
            Map.entry("SUB3B", "XC=-30,YC=-40,RA=5,XA3=-35,XB3=-25"),
            Map.entry("SUB3E", "XC=-30,YC=20,RA=10,XA3=-40,XB3=-20,AFAS=20,N=3"),
            Map.entry("SUB4", "XC=26,YC=24,RA=16,XA4=10,YA4=24,XB4=42,YB4=24"),
            Map.entry("SUB5A", "XC1=-35,YC1=-35,XC2=-25,YC2=-35,XT=-30,YT=-35,XA5=-40,XB5=-20"),
            Map.entry("SUB5B", "XC1=-30,YC1=-10,XC2=-20,YC2=-10,XT=-25,YT=-10,XA5=-35,XB5=-15"),
            Map.entry("SUB5E", "XC1=-35,YC1=-45,XC2=-25,YC2=-35,XT=-30,YT=-40,XA5=-40,XB5=-20,AFAS=20,N=3"),
            Map.entry("SUB7A", "XA7=-40,YA7=20,XB7=10,YB7=5,XC7=10,YC7=-5"),
            Map.entry("SUB7B", "XB7=10,YB7=8,XC7=10,YC7=-8"),
            Map.entry("SUB8A", "XA8=-39,YA8=20,XB8=4,YB8=0,XC8=5,YC8=-10,XD8=4,YD8=0"),
            Map.entry("SUB8B", "XB8=5,YB8=5,XC8=10,YC8=0,XD8=5,YD8=-5"),
            Map.entry("SUB9A", "XA9=15,YA9=15,XB9=5,YB9=0,XC9=-5,YC9=10,XD9=-5,YD9=0,XE9=5,YE9=-10"),
            Map.entry("SUB9B", "XB9=5,YB9=0,XC9=5,YC9=8,XD9=5,YD9=0,XE9=5,YE9=-8"),
            // the special designs: the closed SUB9A parallelograms of test 05 as a lattice, and
            // fields of the same size (ours: the thesis has no call for them)
            Map.entry("PARAL", "XO=10,YO=15,A=5,B=11.18034,ANG=116.56505,NA=4,NB=2"),
            Map.entry("COLMEIA", "XO=-30,YO=-30,S=5,NX=6,NY=5"),
            Map.entry("PIRAM", "XO=-30,YO=-30,P=6,ANG=45,N1=6,N2=6"),
            Map.entry("TEXTURA", "XO=-30,YO=-30,L=60,P=3,ANG=0,N=6,DASH=4,GAP=2"),
            Map.entry("LOGO", "X=-20,Y=-10,H=20"));

    private static final Set<String> IGNORED = Set.of("I", "PROF", "AVAN");

    private TreadFigures() {}

    /** The thesis's parameter names of a macro, in its order (without CTM, PROF, AVAN, I). */
    public static List<String> parameters(String macro) {
        List<String> p = PARAMS.get(macro.toUpperCase(Locale.ROOT));
        if (p == null) {
            throw new IllegalArgumentException("unknown macro " + macro);
        }
        return p;
    }

    /**
     * The parameters of the macro's call in one of the thesis's programs (App. E test programs;
     * SUB1B from the insert program of App. F), as {@code NAME=value,...}: previews and defaults.
     */
    public static String thesisExample(String macro) {
        String e = EXAMPLES.get(macro.toUpperCase(Locale.ROOT));
        if (e == null) {
            throw new IllegalArgumentException("unknown macro " + macro);
        }
        return e;
    }

    /** Whether the macro is one of the special designs of Table 5.2 (groups F to J). */
    public static boolean isSpecial(String macro) {
        return SpecialDesigns.MACROS.contains(macro.toUpperCase(Locale.ROOT));
    }

    /** Whether the macro draws a drawing's outlines (LOGO), which a file must give. */
    public static boolean needsDrawing(String macro) {
        return macro.trim().equalsIgnoreCase("LOGO");
    }

    /** Whether the macro carries on the groove in progress (B, E-less continuous types, PRIM/NOVO excluded). */
    public static boolean isContinuous(String macro) {
        return Set.of("SUB3B", "SUB5B", "SUB7B", "SUB8B", "SUB9B").contains(macro.toUpperCase(Locale.ROOT));
    }

    /**
     * Parses {@code "XA1=-40, YA1=-41, ..."} (commas or blanks between, as in a CALL).
     *
     * @throws CamInputException for a malformed pair or number
     */
    public static Map<String, Double> parseParams(String text, String source) throws CamInputException {
        Map<String, Double> out = new LinkedHashMap<>();
        for (String tok : text.trim().split("[,\\s]+")) {
            if (tok.isEmpty()) {
                continue;
            }
            int eq = tok.indexOf('=');
            if (eq <= 0) {
                throw new CamInputException(source, "expected NAME=value in figure parameters, found '" + tok + "'");
            }
            String k = tok.substring(0, eq).trim().toUpperCase(Locale.ROOT);
            try {
                double v = Double.parseDouble(tok.substring(eq + 1).trim());
                if (!Double.isFinite(v) || Math.abs(v) > 1e6) {
                    throw new NumberFormatException();
                }
                if (out.put(k, v) != null) {
                    throw new CamInputException(source, "figure parameter " + k + " given twice");
                }
            } catch (NumberFormatException e) {
                throw new CamInputException(
                        source, "figure parameter " + k + ": expected a number, found '" + tok.substring(eq + 1) + "'");
            }
        }
        return out;
    }

    /**
     * The figure of a macro with its parameters; the path is computed once to check that the
     * parameters give one.
     *
     * @throws CamInputException naming a missing, unknown or inconsistent parameter
     */
    public static TreadFigure of(String macro, Map<String, Double> params, String source) throws CamInputException {
        return of(macro, params, List.of(), source);
    }

    /**
     * As {@link #of(String, Map, String)}, with the outlines of a drawing for LOGO (ignored by
     * every other macro).
     *
     * @param drawing the drawing's chains of lines and arcs, in its frame
     */
    public static TreadFigure of(
            String macro, Map<String, Double> params, List<List<org.fresa.geom.Curve2>> drawing, String source)
            throws CamInputException {
        String m = macro.trim().toUpperCase(Locale.ROOT);
        List<String> names = PARAMS.get(m);
        if (names == null) {
            throw new CamInputException(source, "unknown tread macro '" + macro + "', expected one of " + MACROS);
        }
        Map<String, Double> p = new LinkedHashMap<>();
        params.forEach((k, v) -> p.put(k.toUpperCase(Locale.ROOT), v));
        Set<String> allowed = new TreeSet<>(names);
        allowed.addAll(IGNORED);
        allowed.add("CTM");
        allowed.add("CCW");
        for (String k : p.keySet()) {
            if (!allowed.contains(k)) {
                throw new CamInputException(source, m + ": unknown parameter " + k + ", expected " + names);
            }
        }
        for (String k : names) {
            if (!p.containsKey(k)) {
                throw new CamInputException(source, m + ": missing parameter " + k + " (needs " + names + ")");
            }
        }
        if (p.getOrDefault("CTM", 0.0) != 0.0) {
            throw new CamInputException(source, m + ": CTM (shrinkage) is set for the whole sole job, not per figure");
        }
        boolean ccw = p.getOrDefault("CCW", 0.0) != 0.0;
        TreadFigure f;
        try {
            f = m.equals("LOGO")
                    ? new SpecialDesigns.Logo(p.get("X"), p.get("Y"), p.get("H"), drawing)
                    : build(m, p, ccw);
            f.path(Vec2.ZERO, Tolerance.DEFAULT);
        } catch (IllegalArgumentException e) {
            throw new CamInputException(source, m + ": " + e.getMessage());
        }
        return f;
    }

    private static TreadFigure build(String m, Map<String, Double> p, boolean ccw) {
        java.util.function.ToDoubleFunction<String> g = p::get;
        return switch (m) {
            case "PRIM" ->
                new TreadFigure.Prim(
                        g.applyAsDouble("XI"), g.applyAsDouble("YI"), g.applyAsDouble("XA1"), g.applyAsDouble("YA1"));
            case "NOVO" ->
                new TreadFigure.Novo(
                        g.applyAsDouble("XF1"), g.applyAsDouble("YF1"), g.applyAsDouble("XF2"), g.applyAsDouble("YF2"));
            case "SUB1A" ->
                new TreadFigure.Sub1a(
                        g.applyAsDouble("XA1"),
                        g.applyAsDouble("YA1"),
                        g.applyAsDouble("XB1"),
                        g.applyAsDouble("YC1"),
                        g.applyAsDouble("XC1"),
                        g.applyAsDouble("XD1"));
            case "SUB1B" ->
                new TreadFigure.Sub1b(
                        g.applyAsDouble("XA1"),
                        g.applyAsDouble("YA1"),
                        g.applyAsDouble("YB1"),
                        g.applyAsDouble("YC1"),
                        g.applyAsDouble("XC1"),
                        g.applyAsDouble("YD1"));
            case "SUB2" ->
                new TreadFigure.Sub2(
                        g.applyAsDouble("XA2"), g.applyAsDouble("YA2"), g.applyAsDouble("XB2"), g.applyAsDouble("YB2"));
            case "SUB3A" ->
                new TreadFigure.Sub3a(
                        g.applyAsDouble("XC"),
                        g.applyAsDouble("YC"),
                        positive(g, "RA"),
                        g.applyAsDouble("XA3"),
                        g.applyAsDouble("XB3"),
                        ccw);
            case "SUB3B" ->
                new TreadFigure.Sub3b(
                        g.applyAsDouble("XC"),
                        g.applyAsDouble("YC"),
                        positive(g, "RA"),
                        g.applyAsDouble("XA3"),
                        g.applyAsDouble("XB3"),
                        ccw);
            case "SUB3E" ->
                new TreadFigure.Sub3e(
                        g.applyAsDouble("XC"),
                        g.applyAsDouble("YC"),
                        positive(g, "RA"),
                        g.applyAsDouble("XA3"),
                        g.applyAsDouble("XB3"),
                        g.applyAsDouble("AFAS"),
                        count(g, "N"),
                        ccw);
            case "SUB4" ->
                new TreadFigure.Sub4(
                        g.applyAsDouble("XC"),
                        g.applyAsDouble("YC"),
                        positive(g, "RA"),
                        g.applyAsDouble("XA4"),
                        g.applyAsDouble("YA4"),
                        g.applyAsDouble("XB4"),
                        g.applyAsDouble("YB4"),
                        ccw);
            case "SUB5A" ->
                new TreadFigure.Sub5a(
                        g.applyAsDouble("XC1"),
                        g.applyAsDouble("YC1"),
                        g.applyAsDouble("XC2"),
                        g.applyAsDouble("YC2"),
                        g.applyAsDouble("XT"),
                        g.applyAsDouble("YT"),
                        g.applyAsDouble("XA5"),
                        g.applyAsDouble("XB5"),
                        ccw);
            case "SUB5B" ->
                new TreadFigure.Sub5b(
                        g.applyAsDouble("XC1"),
                        g.applyAsDouble("YC1"),
                        g.applyAsDouble("XC2"),
                        g.applyAsDouble("YC2"),
                        g.applyAsDouble("XT"),
                        g.applyAsDouble("YT"),
                        g.applyAsDouble("XA5"),
                        g.applyAsDouble("XB5"),
                        ccw);
            case "SUB5E" ->
                new TreadFigure.Sub5e(
                        g.applyAsDouble("XC1"),
                        g.applyAsDouble("YC1"),
                        g.applyAsDouble("XC2"),
                        g.applyAsDouble("YC2"),
                        g.applyAsDouble("XT"),
                        g.applyAsDouble("YT"),
                        g.applyAsDouble("XA5"),
                        g.applyAsDouble("XB5"),
                        g.applyAsDouble("AFAS"),
                        count(g, "N"),
                        ccw);
            case "SUB7A" ->
                new TreadFigure.Sub7a(
                        g.applyAsDouble("XA7"),
                        g.applyAsDouble("YA7"),
                        g.applyAsDouble("XB7"),
                        g.applyAsDouble("YB7"),
                        g.applyAsDouble("XC7"),
                        g.applyAsDouble("YC7"));
            case "SUB7B" ->
                new TreadFigure.Sub7b(
                        g.applyAsDouble("XB7"), g.applyAsDouble("YB7"), g.applyAsDouble("XC7"), g.applyAsDouble("YC7"));
            case "SUB8A" ->
                new TreadFigure.Sub8a(
                        g.applyAsDouble("XA8"),
                        g.applyAsDouble("YA8"),
                        g.applyAsDouble("XB8"),
                        g.applyAsDouble("YB8"),
                        g.applyAsDouble("XC8"),
                        g.applyAsDouble("YC8"),
                        g.applyAsDouble("XD8"),
                        g.applyAsDouble("YD8"));
            case "SUB8B" ->
                new TreadFigure.Sub8b(
                        g.applyAsDouble("XB8"),
                        g.applyAsDouble("YB8"),
                        g.applyAsDouble("XC8"),
                        g.applyAsDouble("YC8"),
                        g.applyAsDouble("XD8"),
                        g.applyAsDouble("YD8"));
            case "SUB9A" ->
                new TreadFigure.Sub9a(
                        g.applyAsDouble("XA9"),
                        g.applyAsDouble("YA9"),
                        g.applyAsDouble("XB9"),
                        g.applyAsDouble("YB9"),
                        g.applyAsDouble("XC9"),
                        g.applyAsDouble("YC9"),
                        g.applyAsDouble("XD9"),
                        g.applyAsDouble("YD9"),
                        g.applyAsDouble("XE9"),
                        g.applyAsDouble("YE9"));
            case "SUB9B" ->
                new TreadFigure.Sub9b(
                        g.applyAsDouble("XB9"),
                        g.applyAsDouble("YB9"),
                        g.applyAsDouble("XC9"),
                        g.applyAsDouble("YC9"),
                        g.applyAsDouble("XD9"),
                        g.applyAsDouble("YD9"),
                        g.applyAsDouble("XE9"),
                        g.applyAsDouble("YE9"));
            case "PARAL" ->
                new SpecialDesigns.Parallelograms(
                        g.applyAsDouble("XO"),
                        g.applyAsDouble("YO"),
                        g.applyAsDouble("A"),
                        g.applyAsDouble("B"),
                        g.applyAsDouble("ANG"),
                        count(g, "NA"),
                        count(g, "NB"));
            case "COLMEIA" ->
                new SpecialDesigns.Honeycomb(
                        g.applyAsDouble("XO"),
                        g.applyAsDouble("YO"),
                        g.applyAsDouble("S"),
                        count(g, "NX"),
                        count(g, "NY"));
            case "PIRAM" ->
                new SpecialDesigns.InvertedPyramids(
                        g.applyAsDouble("XO"),
                        g.applyAsDouble("YO"),
                        g.applyAsDouble("P"),
                        g.applyAsDouble("ANG"),
                        count(g, "N1"),
                        count(g, "N2"));
            case "TEXTURA" ->
                new SpecialDesigns.TextureLines(
                        g.applyAsDouble("XO"),
                        g.applyAsDouble("YO"),
                        g.applyAsDouble("L"),
                        g.applyAsDouble("P"),
                        g.applyAsDouble("ANG"),
                        count(g, "N"),
                        g.applyAsDouble("DASH"),
                        g.applyAsDouble("GAP"));
            default -> throw new IllegalArgumentException("unknown macro " + m);
        };
    }

    private static double positive(java.util.function.ToDoubleFunction<String> g, String k) {
        double v = g.applyAsDouble(k);
        if (!(v > 0)) {
            throw new IllegalArgumentException(k + " must be > 0: " + v);
        }
        return v;
    }

    private static int count(java.util.function.ToDoubleFunction<String> g, String k) {
        double v = g.applyAsDouble(k);
        if (v != Math.rint(v) || v < 1 || v > 1000) {
            throw new IllegalArgumentException(k + " must be a whole number from 1 to 1000: " + v);
        }
        return (int) v;
    }
}
