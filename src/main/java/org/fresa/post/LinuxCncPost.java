package org.fresa.post;

import java.util.List;

/**
 * LinuxCNC's RS274/NGC: parenthesised comments, no block numbers, tool length offset G43 Hn after
 * the tool change, extra helix turns as the P word (P = turns + 1). The default post.
 */
final class LinuxCncPost extends GcodePost {

    LinuxCncPost(double chordToleranceMm) {
        super(Dialect.LINUXCNC, chordToleranceMm);
    }

    @Override
    public String name() {
        return "linuxcnc";
    }

    @Override
    public String description() {
        return "LinuxCNC RS274/NGC (default): G21 G90, G02/G03 in G17/G18/G19, helix turns as P, T M6 G43";
    }

    @Override
    List<String> header(String programName) {
        return List.of("%");
    }

    @Override
    List<String> safeStart() {
        return List.of("G21 G90 G94 G17 G40 G49 G80 G54 G91.1");
    }

    @Override
    List<String> safeEnd() {
        return List.of("M5", "G40 G49 G80", "M30");
    }

    @Override
    List<String> trailer() {
        return List.of("%");
    }
}
