package org.fresa.pocket.compat;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.List;
import java.util.regex.Pattern;
import org.fresa.model.CamInputException;
import org.fresa.pocket.PocketTechnology;

/**
 * The pocket thesis's technology printout and its output name ({@code GOTA.BAS} lines 3400-3470 and
 * 4095-4100): what {@code fresa pocket --report FILE} and {@code --thesis-name NAME} write.
 *
 * <p>The printout is the listing's {@code LPRINT} block line for line: its labels as the listing
 * spells them, the two empty {@code LPRINT} lines, each value in the next 14-column print zone of
 * BASIC's comma, numbers as BASIC prints them (a leading blank for the sign, a trailing blank, at
 * most 7 significant digits, no 0 before the point). The depth passes and their increment are the
 * program's: {@code PROF = INT((ZSUP - ZBASE) / ZPROF + .9999999)}, at least 1, and
 * {@code ZPASSE = (ZSUP - ZBASE) / PROF}. The listing prints the speed and feeds from string
 * variables it never sets ({@code ROTAC$}, {@code AVANS$}, {@code AVANC$} against its
 * {@code INPUT ROTAC%}, {@code AVANC%}); the printed Table 7.2 shows the numbers entered, as
 * written here.
 */
public final class PocketReport {

    /** BASIC's print zone for a comma, characters. */
    static final int ZONE = 14;

    /** The thesis's DOS names: N01 and the name, at most 8 characters, then .DAD. */
    public static final int MAX_THESIS_NAME_CHARS = 5;

    private static final Pattern NAME = Pattern.compile("[A-Za-z0-9]{1," + MAX_THESIS_NAME_CHARS + "}");

    private PocketReport() {}

    /** The printout of the technology. */
    public static String of(PocketTechnology s) {
        double depth = s.zTopMm() - s.zBottomMm();
        int passes = (int) Math.floor(depth / s.maxDepthMm() + .9999999);
        if (passes == 0) {
            passes = 1;
        }
        double increment = depth / passes;
        List<String> lines = List.of(
                zone("DIAMETRO DA FRESA =") + basic(s.toolDiameterMm()),
                zone(" % DE CORTE      =") + basic(s.cutFraction() * 100) + "%",
                zone(" % DE ACABAMENTO   =") + basic(s.finishFraction() * 100) + "%",
                "",
                "",
                zone(" PLANO (Z) DA SUPERFICIE = ") + basic(s.zTopMm()),
                zone(" PLANO (Z) DA BASE      = ") + basic(s.zBottomMm()),
                zone(" PASSE DE PROFUNDIDADE  = ") + basic(s.maxDepthMm()),
                zone(" N DE PASSE DE PROFUND. = ") + basic(passes),
                zone(" INCREMENTO NA PROFUNDID.= ") + basic(increment),
                zone(" ROTACAO DA FRESA       = ") + basic(s.spindleRpm()),
                zone(" AVANCO DA FRESA        = ") + basic(s.feedMmPerMin()),
                zone(" AVANCO NO ACABAMENTO   = ") + basic(s.finishFeedMmPerMin()));
        return String.join("\n", lines) + "\n";
    }

    /** The text padded to the start of BASIC's next print zone (the comma after it). */
    static String zone(String text) {
        int to = (text.length() / ZONE + 1) * ZONE;
        return text + " ".repeat(to - text.length());
    }

    /** A number as BASIC's PRINT writes it: sign or blank, 7 significant digits, no leading 0, a blank after. */
    static String basic(double v) {
        BigDecimal d = new BigDecimal(v).round(MathContext.DECIMAL32).stripTrailingZeros();
        String t = d.abs().toPlainString();
        if (t.startsWith("0.")) {
            t = t.substring(1);
        }
        return (d.signum() < 0 ? "-" : " ") + t + " ";
    }

    /**
     * The thesis's name of the program of an input named {@code name}: {@code N01} and the name,
     * then {@code .DAD} (its diskette holds {@code NO1CV8.DAD} for the input {@code CV8.DAD}).
     *
     * @throws CamInputException (exit 2) unless the name is 1 to 5 letters or digits
     */
    public static String thesisFileName(String name) throws CamInputException {
        if (name == null || !NAME.matcher(name).matches()) {
            throw new CamInputException(
                    "--thesis-name",
                    "'" + name + "': expected 1 to " + MAX_THESIS_NAME_CHARS
                            + " letters or digits (N01 and the name make the thesis's 8-character DOS name)");
        }
        return "N01" + name.toUpperCase(java.util.Locale.ROOT) + ".DAD";
    }
}
