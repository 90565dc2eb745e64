package org.fresa.post;

import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * The machine-tool posts by name: {@code linuxcnc} (the default), {@code iso}, {@code fanuc},
 * {@code 840d}, {@code apt}. Names are matched ignoring case. Every G-code post here writes arcs
 * as G02/G03 in G17/G18/G19 and replaces arcs in other planes by chords within
 * {@link #CHORD_TOLERANCE_MM}; the APT post ({@link AptPost}) writes every arc as a CIRCLE.
 */
public final class NcPosts {

    /** The chord tolerance of the registered posts for arcs outside the principal planes, mm. */
    public static final double CHORD_TOLERANCE_MM = GcodePost.DEFAULT_CHORD_TOLERANCE_MM;

    /** The name of the default post. */
    public static final String DEFAULT = "linuxcnc";

    private static final List<String> TAPE = List.of("%");

    private static final List<NcPost> ALL = List.of(
            // LinuxCNC's RS274/NGC: no block numbers, tool length offset G43 Hn after the tool change,
            // extra helix turns as the P word (P = turns + 1)
            new GcodePost(
                    "linuxcnc",
                    "LinuxCNC RS274/NGC (default): G21 G90, G02/G03 in G17/G18/G19, helix turns as P," + " T M6 G43",
                    Dialect.LINUXCNC,
                    new GcodePost.Frame(
                            name -> TAPE,
                            List.of("G21 G90 G94 G17 G40 G49 G80 G54 G91.1"),
                            List.of("M5", "G40 G49 G80", "M30"),
                            TAPE),
                    CHORD_TOLERANCE_MM),
            // plain ISO 6983-1, the common subset most controls read: G21 for millimetres (the de facto
            // code; ISO 6983 itself reserves G71), no tool length offset word (the control's tool data
            // applies it), no turn word: multi-turn helices are one block per turn
            new GcodePost(
                    "iso",
                    "plain ISO 6983: N-numbered blocks, G21 G90, G02/G03 with I/J/K, one block per helix turn",
                    Dialect.ISO,
                    new GcodePost.Frame(
                            name -> TAPE, List.of("G21 G90 G94 G17 G40 G80"), List.of("M5", "G40 G80", "M30"), TAPE),
                    CHORD_TOLERANCE_MM),
            // Fanuc 0i/30i-style milling: tape marks, an O program number, every coordinate with a
            // decimal point, no turn word (one block per helix turn)
            new GcodePost(
                    "fanuc",
                    "Fanuc milling: O number, N blocks, G21 G90, T M06 G43 H, G02/G03 with I/J/K",
                    Dialect.FANUC,
                    new GcodePost.Frame(
                            name -> List.of("%", "O1000"),
                            List.of("G21 G90 G94 G17 G40 G49 G80"),
                            List.of("M05", "G40 G49 G80", "M30"),
                            TAPE),
                    CHORD_TOLERANCE_MM),
            // Siemens Sinumerik 840D in Siemens mode: G71 for millimetres, plain G0/G1/G2/G3 moves without
            // cycles, centre words I/J/K incremental from the start point (the 840D default)
            new GcodePost(
                    "840d",
                    "Siemens Sinumerik 840D: ; comments, N blocks, G71 G90, T D1 M6, plain G2/G3 with"
                            + " incremental I/J/K, TURN=",
                    Dialect.SIEMENS_840D,
                    new GcodePost.Frame(
                            NcPosts::siemensHeader,
                            List.of("G71 G90 G94 G17 G40 G60"),
                            List.of("M5", "G40", "M30"),
                            List.of()),
                    CHORD_TOLERANCE_MM),
            new AptPost());

    /** The 840D's file header: the part program's name in upper case, starting with a letter. */
    private static List<String> siemensHeader(String programName) {
        String name = programName.toUpperCase(Locale.ROOT).replaceAll("[^A-Z0-9_]", "_");
        if (name.isEmpty() || !Character.isLetter(name.charAt(0))) {
            name = "P_" + name;
        }
        return List.of("%_N_" + name + "_MPF", ";$PATH=/_N_MPF_DIR");
    }

    private NcPosts() {}

    /** The post with this name (case-insensitive), or empty. */
    public static Optional<NcPost> byName(String name) {
        String n = name.trim().toLowerCase(Locale.ROOT);
        return ALL.stream().filter(p -> p.name().equals(n)).findFirst();
    }

    /** The default post ({@code linuxcnc}). */
    public static NcPost defaultPost() {
        return ALL.get(0);
    }

    /** Every post, default first. */
    public static List<NcPost> all() {
        return ALL;
    }

    /** The registered names, default first, for messages ("one of linuxcnc, iso, ..."). */
    public static List<String> names() {
        return ALL.stream().map(NcPost::name).toList();
    }
}
