package org.fresa.post;

import java.util.List;
import java.util.Optional;

/**
 * Fanuc 0i/30i-style milling: tape marks, an O program number with the name as comment
 * (upper case, as Fanuc's character set expects), block numbers, T Mn6 then G43 Hn, every
 * coordinate with a decimal point, no turn word (one block per helix turn).
 */
final class FanucPost extends GcodePost {

    FanucPost(double chordToleranceMm) {
        super(chordToleranceMm);
    }

    @Override
    public String name() {
        return "fanuc";
    }

    @Override
    public String description() {
        return "Fanuc milling: O number, N blocks, G21 G90, T M06 G43 H, G02/G03 with I/J/K";
    }

    @Override
    boolean blockNumbers() {
        return true;
    }

    @Override
    String comment(String text) {
        return "(" + plain(text).toUpperCase(java.util.Locale.ROOT) + ")";
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
    List<String> toolChange(int tool) {
        return List.of("M05", "T" + tool + " M06", "G43 H" + tool);
    }

    @Override
    List<String> spindleOn(long rpm) {
        return List.of("S" + rpm + " M03");
    }

    @Override
    List<String> safeEnd() {
        return List.of("M05", "G40 G49 G80", "M30");
    }

    @Override
    List<String> trailer() {
        return List.of("%");
    }

    @Override
    Optional<String> turnsWord(int extraTurns) {
        return Optional.empty();
    }
}
