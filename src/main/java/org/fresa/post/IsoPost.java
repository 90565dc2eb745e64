package org.fresa.post;

import java.util.List;

/**
 * Plain ISO 6983-1 word addresses, the common subset most controls read: block numbers, G21 for
 * millimetres (the de facto code; ISO 6983 itself reserves G71), no tool length offset word (the
 * control's tool data applies it), no turn word: multi-turn helices are one block per turn.
 */
final class IsoPost extends GcodePost {

    IsoPost(double chordToleranceMm) {
        super(Dialect.ISO, chordToleranceMm);
    }

    @Override
    public String name() {
        return "iso";
    }

    @Override
    public String description() {
        return "plain ISO 6983: N-numbered blocks, G21 G90, G02/G03 with I/J/K, one block per helix turn";
    }

    @Override
    List<String> header(String programName) {
        return List.of("%");
    }

    @Override
    List<String> safeStart() {
        return List.of("G21 G90 G94 G17 G40 G80");
    }

    @Override
    List<String> safeEnd() {
        return List.of("M5", "G40 G80", "M30");
    }

    @Override
    List<String> trailer() {
        return List.of("%");
    }
}
