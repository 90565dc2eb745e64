package org.fresa.post;

import java.util.List;

/**
 * Fanuc 0i/30i-style milling: tape marks, an O program number with the name as comment
 * (upper case, as Fanuc's character set expects), block numbers, T Mn6 then G43 Hn, every
 * coordinate with a decimal point, no turn word (one block per helix turn), dwells as G04 X in
 * seconds.
 */
final class FanucPost extends GcodePost {

    FanucPost(double chordToleranceMm) {
        super(Dialect.FANUC, chordToleranceMm);
    }

    @Override
    public String name() {
        return "fanuc";
    }

    @Override
    public String description() {
        return "Fanuc milling: O number, N blocks, G21 G90, T M06 G43 H, G02/G03 with I/J/K";
    }

    /** Upper case: the character set of Fanuc's tape code has no lower-case letters. */
    @Override
    String comment(String text) {
        return dialect().comment(plain(text).toUpperCase(java.util.Locale.ROOT));
    }

    @Override
    List<String> header(String programName) {
        return List.of("%", "O1000");
    }

    @Override
    List<String> safeStart() {
        return List.of("G21 G90 G94 G17 G40 G49 G80");
    }

    @Override
    List<String> safeEnd() {
        return List.of("M05", "G40 G49 G80", "M30");
    }

    @Override
    List<String> trailer() {
        return List.of("%");
    }
}
