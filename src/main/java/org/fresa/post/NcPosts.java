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

    private static final List<NcPost> ALL = List.of(
            new LinuxCncPost(CHORD_TOLERANCE_MM),
            new IsoPost(CHORD_TOLERANCE_MM),
            new FanucPost(CHORD_TOLERANCE_MM),
            new Sinumerik840dPost(CHORD_TOLERANCE_MM),
            new AptPost());

    private NcPosts() {
    }

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
