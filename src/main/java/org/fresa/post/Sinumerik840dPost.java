package org.fresa.post;

import java.util.List;
import java.util.Locale;

/**
 * Siemens Sinumerik 840D in Siemens mode: {@code ;} comments, block numbers, G71 for
 * millimetres, T then D1 and M6, plain G0/G1/G2/G3 moves without cycles, centre words I/J/K
 * incremental from the start point (the 840D default), extra helix turns as {@code TURN=}.
 */
final class Sinumerik840dPost extends GcodePost {

    Sinumerik840dPost(double chordToleranceMm) {
        super(Dialect.SIEMENS_840D, chordToleranceMm);
    }

    @Override
    public String name() {
        return "840d";
    }

    @Override
    public String description() {
        return "Siemens Sinumerik 840D: ; comments, N blocks, G71 G90, T D1 M6, plain G2/G3 with incremental I/J/K, TURN=";
    }

    @Override
    List<String> header(String programName) {
        String name = programName.toUpperCase(Locale.ROOT).replaceAll("[^A-Z0-9_]", "_");
        if (name.isEmpty() || !Character.isLetter(name.charAt(0))) {
            name = "P_" + name;
        }
        return List.of("%_N_" + name + "_MPF", ";$PATH=/_N_MPF_DIR");
    }

    @Override
    List<String> safeStart() {
        return List.of("G71 G90 G94 G17 G40 G60");
    }

    @Override
    List<String> safeEnd() {
        return List.of("M5", "G40", "M30");
    }
}
